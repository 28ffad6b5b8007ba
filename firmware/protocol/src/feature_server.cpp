#include "lumavel/protocol/feature_server.hpp"

namespace lumavel::protocol {

FeatureServer::FeatureServer(const DeviceInfo& identity, hal::ConfigStore* store, ApplyFn apply,
                             void* ctx)
    : info_(identity), store_(store), apply_(apply), ctx_(ctx) {
  info_.config_status = static_cast<uint8_t>(ConfigField::kOk);
  info_.config_source = kConfigDefaults;
}

ConfigField FeatureServer::apply_and_keep(const DeviceConfig& c, uint8_t source) {
  const ConfigField v = validate(c);
  if (v != ConfigField::kOk) return v;
  // Every table the configuration names must be complete and be the one it was made for.
  const EdgeOffsetQ15* tables[2] = {nullptr, nullptr};
  for (int i = 0; i < 2; ++i) {
    if ((c.lens & (1u << i)) == 0) continue;
    if (lens_.filled[i] != c.width + 1u) return ConfigField::kLens;
    tables[i] = lens_.offsets[i];
  }
  if (lens_crc(tables, c.lens, static_cast<uint16_t>(c.width + 1u)) != c.lens_crc) return ConfigField::kLens;
  const ConfigField a = apply_ != nullptr ? apply_(ctx_, c, tables) : ConfigField::kOk;
  if (a != ConfigField::kOk) return a;
  config_ = c;
  info_.width = c.width;
  info_.height = c.height;
  info_.config_source = source;
  return ConfigField::kOk;
}

// The blob buffer (up to 618 bytes on a 128-column board) lives in these two
// out-of-line functions only, so that it is never on the stack while the
// configuration is applied (kernel tables built): the two peaks do not add.
__attribute__((noinline)) bool FeatureServer::load_stored(DeviceConfig& out) {
  uint8_t buf[kMaxStoredConfigSize];
  const size_t n = store_->load(buf, sizeof buf);
  return n > 0 && decode_stored_config(buf, n, out, lens_) == ConfigField::kOk;
}

__attribute__((noinline)) bool FeatureServer::save_current() {
  uint8_t out[kMaxStoredConfigSize];
  const size_t n = encode_stored_config(config_, lens_, out, sizeof out);
  return n != 0 && store_->save(out, n);
}

ConfigField FeatureServer::boot(const DeviceConfig& defaults) {
  DeviceConfig stored{};
  if (store_ != nullptr && load_stored(stored) && apply_and_keep(stored, kConfigStored) == ConfigField::kOk) {
    info_.config_status = static_cast<uint8_t>(ConfigField::kOk);
    return ConfigField::kOk;
  }
  lens_.filled[0] = lens_.filled[1] = 0;
  const ConfigField r = apply_and_keep(defaults, kConfigDefaults);
  info_.config_status = static_cast<uint8_t>(r);
  return r;
}

ConfigField FeatureServer::set_config(const uint8_t* buf, size_t len) {
  DeviceConfig c{};
  ConfigField r = parse_config(buf, len, c);
  if (r == ConfigField::kOk) r = apply_and_keep(c, kConfigSetByHost);
  if (r == ConfigField::kOk && store_ != nullptr && !save_current()) {
    r = ConfigField::kStore;  // in force until reboot, but not persisted
  }
  info_.config_status = static_cast<uint8_t>(r);
  return r;
}

ConfigField FeatureServer::set_lens(const uint8_t* buf, size_t len) {
  LensChunk c{};
  ConfigField r = ConfigField::kMalformed;
  if (decode_lens_chunk(buf, len, c).ok()) r = store_lens_chunk(lens_, c) ? ConfigField::kOk : ConfigField::kLens;
  info_.config_status = static_cast<uint8_t>(r);
  return r;
}

size_t FeatureServer::handle(void* ctx, uint8_t id, bool is_set, uint8_t* buf, size_t len,
                             size_t cap) {
  FeatureServer& s = *static_cast<FeatureServer*>(ctx);
  if (is_set) {
    if (id == kReportConfig) return s.set_config(buf, len) == ConfigField::kOk ? 1 : 0;
    if (id == kReportLens) return s.set_lens(buf, len) == ConfigField::kOk ? 1 : 0;
    return 0;
  }
  if (id == kReportDeviceInfo) return encode_device_info(s.info_, buf, cap);
  if (id == kReportConfig) return encode_config(s.config_, buf, cap);
  if (id == kReportLens) return encode_lens_chunk(selected_lens_chunk(s.lens_), buf, cap);
  return 0;  // stall
}

}  // namespace lumavel::protocol
