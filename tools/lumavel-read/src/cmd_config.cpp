// `config get` and `config set [--file FILE] [KEY=VALUE...]`, lens tables included.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <stdexcept>
#include <thread>

#include "commands.hpp"
#include "device.hpp"
#include "lumavel/host/cli.hpp"
#include "lumavel/host/config_text.hpp"
#include "lumavel/protocol/lens.hpp"

namespace lumavel::read {

namespace proto = lumavel::protocol;
using host::DeviceSetup;

namespace {

// Some USB stacks (Linux gadget HID) acknowledge a SET_REPORT before the
// device has read it and keep only the latest one: sets sent back to back can
// overwrite each other. A short pause after each set lets the device take it;
// what is still lost shows in the read-back and is sent again.
void pause_after_set() { std::this_thread::sleep_for(std::chrono::milliseconds(10)); }

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

// Sends lens pieces of `t` for camera `cam`, 24 values each, in order.
void upload_lens(Device& dev, uint8_t cam, const std::vector<EdgeOffsetQ15>& t) {
  for (size_t i = 0; i < proto::lens_piece_count(t.size()); ++i) {
    uint8_t buf[proto::kLensChunkSize];
    proto::encode_lens_chunk(proto::lens_piece(cam, t.data(), t.size(), i), buf, sizeof buf);
    dev.set_feature(buf, sizeof buf);
    pause_after_set();
  }
}

// One piece: select it, then get it. The answer must be the piece selected
// (a select overwritten by the get's mailbox request is tried again).
proto::LensChunk read_piece(Device& dev, uint8_t cam, uint8_t first) {
  proto::LensChunk sel{};
  sel.camera = cam;
  sel.first = first;
  uint8_t buf[proto::kLensChunkSize];
  proto::encode_lens_chunk(sel, buf, sizeof buf);
  constexpr int kTries = 3;
  for (int attempt = 1;; ++attempt) {
    try {
      dev.set_feature(buf, sizeof buf);
      pause_after_set();
      const auto raw = dev.get_feature(proto::kReportLens, [&sel](const uint8_t* b, size_t n) {
        proto::LensChunk c{};
        proto::DecodeResult r = proto::decode_lens_chunk(b, n, c);
        if (r.ok() && (c.camera != sel.camera || c.first != sel.first || c.count == 0))
          r = proto::DecodeResult{proto::ReportError::kOutOfRange, "lens piece (not the one selected)"};
        return r;
      });
      proto::LensChunk c{};
      proto::decode_lens_chunk(raw.data(), raw.size(), c);
      return c;
    } catch (const DeviceError& e) {
      if (e.kind() != DeviceErrorKind::kProtocol || attempt == kTries) throw;
    }
  }
}

// The device's table for camera `cam`, piece by piece.
std::vector<EdgeOffsetQ15> read_lens(Device& dev, uint8_t cam, size_t edges) {
  std::vector<EdgeOffsetQ15> out;
  while (out.size() < edges) {
    const proto::LensChunk c = read_piece(dev, cam, static_cast<uint8_t>(out.size()));
    for (size_t i = 0; i < c.count && out.size() < edges; ++i) out.push_back(c.offsets[i]);
  }
  return out;
}

DeviceSetup read_setup(Device& dev) {
  DeviceSetup s;
  s.config = read_config(dev);
  for (uint8_t cam = 0; cam < 2; ++cam)
    if (s.config.lens & (1u << cam)) s.lens[cam] = read_lens(dev, cam, size_t{s.config.width} + 1);
  return s;
}

bool same(const DeviceSetup& a, const DeviceSetup& b) {
  uint8_t x[proto::kConfigSize], y[proto::kConfigSize];
  proto::encode_config(a.config, x, sizeof x);
  proto::encode_config(b.config, y, sizeof y);
  return std::equal(x, x + sizeof x, y) && a.lens[0] == b.lens[0] && a.lens[1] == b.lens[1];
}

int set_config(Device& dev, const host::GivenSettings& given) {
  const DeviceSetup current = read_setup(dev);
  const std::string why = host::check_settings(current, given);
  if (!why.empty()) {
    std::fprintf(stderr, "lumavel-read config set: %s (with the device's configuration; nothing sent)\n", why.c_str());
    return kExitRefused;
  }
  DeviceSetup want = current;
  given.apply_to(want);
  host::seal_lens(want);
  uint8_t buf[proto::kConfigSize];
  proto::encode_config(want.config, buf, sizeof buf);
  // A set is idempotent: when the read-back shows it did not arrive (a lost
  // transfer was seen on the gadget link under emulation), send it again.
  constexpr int kAttempts = 3;
  for (int attempt = 1;; ++attempt) {
    bool refused_by_link = false;
    try {
      for (uint8_t cam = 0; cam < 2; ++cam) upload_lens(dev, cam, want.lens[cam]);
      dev.set_feature(buf, sizeof buf);
      pause_after_set();
    } catch (const DeviceError&) {
      refused_by_link = true;  // the reason is in the info report
    }
    const proto::DeviceInfo info = read_info(dev);
    const auto status = static_cast<proto::ConfigField>(info.config_status);
    // An incomplete table is what a lost piece looks like: send everything again.
    const bool lost_piece = status == proto::ConfigField::kLens && want.config.lens != 0 && attempt < kAttempts;
    if (lost_piece) {
      std::fprintf(stderr, "lumavel-read config set: the device missed a lens piece, sending again (attempt %d of %d)\n",
                   attempt + 1, kAttempts);
      continue;
    }
    if (refused_by_link || info.config_status != 0) {
      std::fprintf(stderr, "lumavel-read config set: the device refused the configuration: %s\n",
                   proto::to_string(static_cast<proto::ConfigField>(info.config_status)));
      return kExitRefused;
    }
    const DeviceSetup now = read_setup(dev);
    if (same(now, want)) {
      std::fputs(host::format_setup(now).c_str(), stdout);
      break;
    }
    if (attempt == kAttempts) {
      std::fputs(host::format_setup(now).c_str(), stdout);
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

}  // namespace

host::GivenSettings ConfigInput::read_and_check() const {
  host::GivenSettings given;
  for (const std::string& f : files) given.add_file(f);
  given.add_command_line(settings);
  host::check_settings_offline(given);
  return given;
}

int cmd_config_get(const Common& c) {
  Device dev(load_hidapi(c.backend_kind()), c.device);
  std::fputs(host::format_setup(read_setup(dev)).c_str(), stdout);
  return kExitOk;
}

int cmd_config_set(const Common& c, const ConfigInput& in) {
  if (in.files.empty() && in.settings.empty()) throw cli::UsageError("nothing to set: give --file FILE or KEY=VALUE");
  const host::GivenSettings given = in.read_and_check();  // before any device is opened
  Device dev(load_hidapi(c.backend_kind()), c.device);
  return set_config(dev, given);
}

int cmd_config_check(const ConfigInput& in) {
  if (in.files.empty() && in.settings.empty()) throw cli::UsageError("nothing to check: give --file FILE or KEY=VALUE");
  const host::GivenSettings given = in.read_and_check();
  std::printf("ok: %zu setting(s) checked", given.items.size());
  for (const std::string& f : in.files) std::printf(", %s", f.c_str());
  std::printf("\n");
  return kExitOk;
}

}  // namespace lumavel::read
