// lumavel-read: list, stream, inspect and configure lumavel HID devices.
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "commands.hpp"
#include "device.hpp"

using namespace lumavel::read;

namespace {

void usage(std::FILE* f) {
  std::fprintf(f,
               "usage: lumavel-read [--backend hidraw|libusb] [--device PATH] COMMAND [args]\n"
               "Talks to lumavel velocity sensors (USB HID 1209:0001) through hidapi.\n"
               "commands:\n"
               "  list                      lumavel devices seen by the backend\n"
               "  stream [-o CSV] [-n N]    input reports as CSV, or a live line on a terminal\n"
               "  info                      firmware version, board, working resolution\n"
               "  config get                the configuration as KEY=VALUE lines\n"
               "  config set KEY=VALUE...   change, validate, store and read back\n"
               "  replay FILE [-o CSV]      decode a report file (lumavel-sim --hid file:FILE)\n"
               "options:\n"
               "  --backend hidraw|libusb   hidapi backend (default hidraw; libusb detaches the\n"
               "                            kernel driver and reads the USB device directly)\n"
               "  --device PATH             a path from `list` (default: the first device)\n"
               "`lumavel-read COMMAND --help` describes each command.\n"
               "exit status: 0 ok, 1 usage or other error, 2 malformed reports, 3 no device,\n"
               "4 permission denied, 5 configuration refused.\n");
}

}  // namespace

int main(int argc, char** argv) {
  Common common;
  std::vector<std::string> rest;
  try {
    int i = 1;
    for (; i < argc; ++i) {
      const std::string a = argv[i];
      if (a == "-h" || a == "--help") {
        usage(stdout);
        return kExitOk;
      } else if (a == "--backend" && i + 1 < argc) {
        common.backend = parse_backend(argv[++i]);
      } else if (a == "--device" && i + 1 < argc) {
        common.device = argv[++i];
      } else if (!a.empty() && a[0] == '-') {
        std::fprintf(stderr, "lumavel-read: unknown or incomplete option %s\n", a.c_str());
        usage(stderr);
        return kExitUsage;
      } else {
        break;
      }
    }
    if (i >= argc) {
      usage(stderr);
      return kExitUsage;
    }
    const std::string cmd = argv[i];
    const std::vector<std::string> args(argv + i + 1, argv + argc);
    if (cmd == "list") return cmd_list(common, args);
    if (cmd == "stream") return cmd_stream(common, args);
    if (cmd == "info") return cmd_info(common, args);
    if (cmd == "config") return cmd_config(common, args);
    if (cmd == "replay") return cmd_replay(common, args);
    std::fprintf(stderr, "lumavel-read: unknown command \"%s\"\n", cmd.c_str());
    usage(stderr);
    return kExitUsage;
  } catch (const DeviceError& e) {
    std::fprintf(stderr, "lumavel-read: %s\n", e.what());
    switch (e.kind()) {
      case DeviceErrorKind::kPermission: return kExitPermission;
      case DeviceErrorKind::kNoDevice:
      case DeviceErrorKind::kGone: return kExitNoDevice;
      case DeviceErrorKind::kProtocol: return kExitMalformed;
      default: return kExitUsage;
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "lumavel-read: %s\n", e.what());
    return kExitUsage;
  }
}
