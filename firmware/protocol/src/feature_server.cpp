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
  const ConfigField a = apply_ != nullptr ? apply_(ctx_, c) : ConfigField::kOk;
  if (a != ConfigField::kOk) return a;
  config_ = c;
  info_.width = c.width;
  info_.height = c.height;
  info_.config_source = source;
  return ConfigField::kOk;
}

ConfigField FeatureServer::boot(const DeviceConfig& defaults) {
  if (store_ != nullptr) {
    uint8_t buf[kConfigSize];
    const size_t n = store_->load(buf, sizeof buf);
    DeviceConfig stored{};
    if (n == kConfigSize && decode_config(buf, n, stored).ok() &&
        apply_and_keep(stored, kConfigStored) == ConfigField::kOk) {
      info_.config_status = static_cast<uint8_t>(ConfigField::kOk);
      return ConfigField::kOk;
    }
  }
  const ConfigField r = apply_and_keep(defaults, kConfigDefaults);
  info_.config_status = static_cast<uint8_t>(r);
  return r;
}

ConfigField FeatureServer::set_config(const uint8_t* buf, size_t len) {
  DeviceConfig c{};
  ConfigField r = parse_config(buf, len, c);
  if (r == ConfigField::kOk) r = apply_and_keep(c, kConfigSetByHost);
  if (r == ConfigField::kOk && store_ != nullptr) {
    uint8_t out[kConfigSize];
    if (encode_config(config_, out, sizeof out) != kConfigSize || !store_->save(out, sizeof out)) {
      r = ConfigField::kStore;  // in force until reboot, but not persisted
    }
  }
  info_.config_status = static_cast<uint8_t>(r);
  return r;
}

size_t FeatureServer::handle(void* ctx, uint8_t id, bool is_set, uint8_t* buf, size_t len,
                             size_t cap) {
  FeatureServer& s = *static_cast<FeatureServer*>(ctx);
  if (is_set) {
    if (id != kReportConfig) return 0;
    return s.set_config(buf, len) == ConfigField::kOk ? 1 : 0;
  }
  if (id == kReportDeviceInfo) return encode_device_info(s.info_, buf, cap);
  if (id == kReportConfig) return encode_config(s.config_, buf, cap);
  return 0;  // stall
}

}  // namespace lumavel::protocol
