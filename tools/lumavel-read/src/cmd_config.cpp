// `config get` and `config set KEY=VALUE...`.
#include <algorithm>
#include <chrono>
#include <thread>
#include <cstdio>

#include "commands.hpp"
#include "config_keys.hpp"
#include "device.hpp"

namespace lumavel::read {

namespace proto = lumavel::protocol;

namespace {

proto::DeviceConfig read_config(Device& dev) {
  const auto raw = dev.get_feature(proto::kReportConfig, [](const uint8_t* b, size_t n) {
    proto::DeviceConfig c{};
    return proto::decode_config(b, n, c);
  });
  proto::DeviceConfig c{};
  proto::decode_config(raw.data(), raw.size(), c);
  return c;
}

proto::DeviceInfo read_info(Device& dev) {
  const auto raw = dev.get_feature(proto::kReportDeviceInfo, [](const uint8_t* b, size_t n) {
    proto::DeviceInfo d{};
    return proto::decode_device_info(b, n, d);
  });
  proto::DeviceInfo d{};
  proto::decode_device_info(raw.data(), raw.size(), d);
  return d;
}

}  // namespace

int cmd_config(const Common& c, const std::vector<std::string>& args) {
  if (args.empty() || wants_help(args)) {
    std::printf("usage: lumavel-read [--backend B] [--device PATH] config get\n"
                "       lumavel-read [--backend B] [--device PATH] config set KEY=VALUE...\n"
                "get prints the device's configuration as KEY=VALUE lines; set changes the\n"
                "given keys, checks every range before sending, sends the whole configuration\n"
                "(versioned, CRC-protected), then reads back and prints what is in force.\n"
                "The device validates again, applies and stores it.\nKeys:\n%s",
                config_keys_help());
    return args.empty() ? kExitUsage : kExitOk;
  }
  Device dev(load_hidapi(c.backend), c.device);
  if (args[0] == "get" && args.size() == 1) {
    std::fputs(format_config(read_config(dev)).c_str(), stdout);
    return kExitOk;
  }
  if (args[0] != "set" || args.size() < 2) {
    std::fprintf(stderr, "lumavel-read config: use `config get` or `config set KEY=VALUE...`\n");
    return kExitUsage;
  }
  proto::DeviceConfig cfg = read_config(dev);
  for (size_t i = 1; i < args.size(); ++i) apply_setting(cfg, args[i]);
  const proto::ConfigField f = proto::validate(cfg);
  if (f != proto::ConfigField::kOk) {
    std::fprintf(stderr, "lumavel-read config set: %s is out of range (nothing sent)\n",
                 proto::to_string(f));
    return kExitRefused;
  }
  uint8_t buf[proto::kConfigSize];
  proto::encode_config(cfg, buf, sizeof buf);
  // A set is idempotent: when the read-back shows it did not arrive (a lost
  // transfer was seen on the gadget link under emulation), send it again.
  constexpr int kAttempts = 3;
  for (int attempt = 1;; ++attempt) {
    bool refused_by_link = false;
    try {
      dev.set_feature(buf, sizeof buf);
    } catch (const DeviceError&) {
      refused_by_link = true;  // the reason is in the info report
    }
    const proto::DeviceInfo info = read_info(dev);
    if (refused_by_link || info.config_status != 0) {
      std::fprintf(stderr, "lumavel-read config set: the device refused the configuration: %s\n",
                   proto::to_string(static_cast<proto::ConfigField>(info.config_status)));
      return kExitRefused;
    }
    const proto::DeviceConfig now = read_config(dev);
    uint8_t back[proto::kConfigSize];
    proto::encode_config(now, back, sizeof back);
    if (std::equal(back, back + sizeof back, buf)) {
      std::fputs(format_config(now).c_str(), stdout);
      break;
    }
    if (attempt == kAttempts) {
      std::fputs(format_config(now).c_str(), stdout);
      std::fprintf(stderr, "lumavel-read config set: the device reports a different configuration "
                           "than the one sent (%d attempts)\n", kAttempts);
      return kExitRefused;
    }
    std::fprintf(stderr, "lumavel-read config set: not in force yet, sending again (attempt %d of %d)\n",
                 attempt + 1, kAttempts);
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  return kExitOk;
}

}  // namespace lumavel::read
