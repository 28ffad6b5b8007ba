// lumavel-read: list, stream, inspect and configure lumavel HID devices.
// The command line (CLI11, lumavel/host/cli.hpp); the commands are cmd_*.cpp.
#include <cstdio>
#include <functional>
#include <memory>
#include <string>

#include "commands.hpp"
#include "device.hpp"
#include "lumavel/host/cli.hpp"

#ifndef LUMAVEL_VERSION
#define LUMAVEL_VERSION "unknown"
#endif

using namespace lumavel::read;
namespace cli = lumavel::cli;

namespace {

const char* const kExitStatus =
    "Exit status: 0 done, 1 bad input or failure (a configuration refused before\n"
    "anything is sent, malformed reports, a file that cannot be written), 2 usage\n"
    "error, 3 no device, 4 permission denied, 5 the device refused the\n"
    "configuration.";

// Device errors have exit codes of their own; said like every other error,
// "lumavel-read COMMAND: error: what".
cli::Action with_device_errors(const std::string& command, std::function<int()> f) {
  return [command, f] {
    try {
      return f();
    } catch (const DeviceError& e) {
      std::fprintf(stderr, "lumavel-read %s: error: %s\n", command.c_str(), e.what());
      switch (e.kind()) {
        case DeviceErrorKind::kPermission: return static_cast<int>(kExitPermission);
        case DeviceErrorKind::kNoDevice:
        case DeviceErrorKind::kNotHidraw:
        case DeviceErrorKind::kGone: return static_cast<int>(kExitNoDevice);
        default: return static_cast<int>(kExitFailure);
      }
    }
  };
}

void add_stream_options(CLI::App* c, StreamOptions& o, bool live_options) {
  // stream writes its CSV in place, so that it can be followed as it grows: a
  // write error ends it with exit 1 and leaves the rows written until then.
  c->add_option("-o,--output", o.output,
                live_options ? "write the CSV to FILE as it comes (a write error ends the stream\nwith exit 1; the rows before it stay)"
                             : "write the CSV to FILE (nothing is left behind if it\ncannot be written)")
      ->type_name("FILE")
      ->check(cli::path_name());
  // 0 is the default's "no limit" inside: given, it asked for no measurement
  // and got them all.
  c->add_option("-n,--count", o.count, "stop after N measurements (default: no limit)")
      ->type_name("N")
      ->check(cli::whole_number_in(1, 1000000000000LL));
  if (!live_options) return;
  // As --count: 0 is the default's "never" inside; given, it asked to give
  // up at once and waited for ever.
  c->add_option("--timeout", o.timeout_s, "give up after S seconds without a report, (0, 1e9] (default: never)")
      ->type_name("S")
      ->check(cli::positive_number_up_to(1e9));
  c->add_flag("--no-reconnect", o.no_reconnect, "exit when the device goes away instead of waiting for it");
  CLI::Option* live = c->add_flag("--live", o.live, "force the live line on");
  CLI::Option* no_live = c->add_flag("--no-live", o.no_live, "force the live line off");
  live->excludes(no_live);
  c->add_flag("--csv", o.csv_on_tty, "CSV even on a terminal");
}

void add_config_input(CLI::App* c, ConfigInput& in) {
  c->add_option("--file", in.files, "KEY=VALUE lines as `config get` prints them (# comments\nallowed); may be repeated")
      ->type_name("FILE")
      ->check(cli::path_name());
  // --file takes every name after it (a vector option): the settings go
  // before it, or after --; either way they are applied after the files.
  c->add_option("SETTINGS", in.settings,
                "KEY=VALUE settings, applied after the files; give them\n"
                "before --file (which takes every name after it) or after --")
      ->type_name("KEY=VALUE");
}

}  // namespace

int main(int argc, char** argv) {
  cli::Tool tool("lumavel-read",
                 "Talks to lumavel velocity sensors (USB HID 1209:0001) through hidapi.\n"
                 "`lumavel-read COMMAND --help` describes each command.",
                 LUMAVEL_VERSION, kExitStatus);
  auto common = std::make_shared<Common>();
  CLI::App& app = tool.app();
  app.add_option("--backend", common->backend,
                 "hidapi backend (default hidraw; libusb detaches the kernel\ndriver and reads the USB device directly)")
      ->type_name("hidraw|libusb")
      ->check(cli::one_of({"hidraw", "libusb"}));
  app.add_option("--device", common->device, "a path from `list` (default: the first device)")->type_name("PATH")->check(cli::path_name());

  tool.command("list",
               "lumavel devices seen by the backend\n\n"
               "Lists lumavel devices (USB 1209:0001, vendor usage page 0xFF00), one per line:\n"
               "PATH  VID:PID  interface  manufacturer / product / serial.",
               with_device_errors("list", [common] { return cmd_list(*common); }));

  auto stream = std::make_shared<StreamOptions>();
  CLI::App* s = tool.command(
      "stream",
      "input reports as CSV, or a live line on a terminal\n\n"
      "Reads input reports and writes them as CSV (header: timestamp_ns,v_xb_mps,\n"
      "distance_m,heading_rad,status,gyro_offset_radps,frame_index,seq,overruns). When\n"
      "stdout is a terminal it shows a live line (rate, V, distance, heading, status)\n"
      "instead, unless --csv. Lost reports (sequence gaps), duplicated and malformed\n"
      "reports are reported on stderr.",
      with_device_errors("stream", [common, stream] { return cmd_stream(*common, *stream); }));
  add_stream_options(s, *stream, true);

  tool.command("info",
               "firmware version, board, working resolution\n\n"
               "Prints the device information report: firmware version, board, working\n"
               "resolution, build capacities, the outcome of the last configuration set and of\n"
               "the last lens piece, and which cameras have lens pieces uploaded that no\n"
               "configuration set has taken yet (lens_upload_pending).",
               with_device_errors("info", [common] { return cmd_info(*common); }));

  CLI::App* config = tool.command(tool.app(), "config",
                                  "the configuration: get, set, or check a file offline\n\n"
                                  "The device configuration as KEY=VALUE lines. Keys:\n" +
                                      std::string(lumavel::host::config_keys_help()));
  tool.command(*config, "get", "print the device's configuration as KEY=VALUE lines",
               with_device_errors("config get", [common] { return cmd_config_get(*common); }));
  auto set_in = std::make_shared<ConfigInput>();
  CLI::App* set = tool.command(
      *config, "set",
      "change, validate, store and read back\n\n"
      "Changes the given keys (from the files, then from the command line), checks\n"
      "every range before any device is opened (as `config check`), then against the\n"
      "device's configuration, sends the lens tables and the whole configuration\n"
      "(versioned, CRC-protected), reads back and prints what is in force. The device\n"
      "validates again, applies and stores it.",
      with_device_errors("config set", [common, set_in] { return cmd_config_set(*common, *set_in); }));
  add_config_input(set, *set_in);
  auto check_in = std::make_shared<ConfigInput>();
  CLI::App* check = tool.command(
      *config, "check",
      "check a configuration file and settings without any device\n\n"
      "Checks the files and KEY=VALUE settings as `config set` does before it opens a\n"
      "device: every value's form and range, and the rules between the keys given\n"
      "(fu and cu against width, lens tables against width, max_gap_us against\n"
      "frame_period_us). Keys not given are not checked. Prints \"ok\" or the refusal\n"
      "(file, line, key, value, rule).",
      [check_in] { return cmd_config_check(*check_in); });
  add_config_input(check, *check_in);

  auto replay = std::make_shared<StreamOptions>();
  auto replay_file = std::make_shared<std::string>();
  CLI::App* r = tool.command(
      "replay",
      "decode a report file (lumavel-sim run --hid file:FILE)\n\n"
      "Decodes a report file (as written by `lumavel-sim run --hid file:FILE`) into the\n"
      "same CSV as `stream`. Malformed reports are named (record, byte offset) on\n"
      "stderr and make the exit status 1, as do records missing or out of order (a\n"
      "sequence gap: the file holds every report its run sent); the others are still\n"
      "written. A duplicated record is named and skipped.",
      [replay, replay_file] { return cmd_replay(*replay_file, *replay); });
  r->add_option("FILE", *replay_file, "the report file")->required()->type_name("")->check(cli::path_name());
  add_stream_options(r, *replay, false);

  return tool.run(argc, argv);
}
