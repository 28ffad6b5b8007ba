#include "lumavel/app/feature_server.hpp"

namespace lumavel::app {

using namespace protocol;

FeatureServer::FeatureServer(const DeviceInfo& identity, hal::ConfigStore* store, ApplyFn apply,
                             void* ctx)
    : info_(identity), store_(store), apply_(apply), ctx_(ctx) {
  info_.config_status = static_cast<uint8_t>(ConfigField::kOk);
  info_.config_source = kConfigDefaults;
  info_.lens_status = static_cast<uint8_t>(ConfigField::kOk);
  info_.staged = 0;
}

bool FeatureServer::pick_tables(const DeviceConfig& c, const EdgeOffsetQ15* tables[2]) const {
  const uint16_t edges = static_cast<uint16_t>(c.width + 1u);
  // Candidates per camera: [0] staged, [1] in force; null where not complete.
  const EdgeOffsetQ15* cand[2][2] = {{nullptr, nullptr}, {nullptr, nullptr}};
  for (int i = 0; i < 2; ++i) {
    if ((c.lens & (1u << i)) == 0) continue;
    if (staged_.filled[i] == edges) cand[i][0] = staged_.offsets[i];
    if (lens_.filled[i] == edges) cand[i][1] = lens_.offsets[i];
  }
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b) {
      const EdgeOffsetQ15* t[2] = {cand[0][a], cand[1][b]};
      bool complete = true;
      for (int i = 0; i < 2; ++i) complete = complete && ((c.lens & (1u << i)) == 0 || t[i] != nullptr);
      if (!complete || lens_crc(t, c.lens, edges) != c.lens_crc) continue;
      tables[0] = t[0];
      tables[1] = t[1];
      return true;
    }
  return false;
}

ConfigField FeatureServer::apply_and_keep(const DeviceConfig& c, uint8_t source) {
  const ConfigField v = validate(c);
  if (v != ConfigField::kOk) return v;
  // Every table the configuration names must be complete and be the one it was made for.
  const EdgeOffsetQ15* tables[2] = {nullptr, nullptr};
  if (!pick_tables(c, tables)) return ConfigField::kLens;
  const ConfigField a = apply_ != nullptr ? apply_(ctx_, c, tables) : ConfigField::kOk;
  if (a != ConfigField::kOk) return a;
  // The tables in force are now exactly those c names.
  for (int i = 0; i < 2; ++i) {
    if (tables[i] == nullptr) {
      lens_.filled[i] = 0;
      continue;
    }
    if (tables[i] != lens_.offsets[i])
      for (uint16_t u = 0; u <= c.width; ++u) lens_.offsets[i][u] = tables[i][u];
    lens_.filled[i] = static_cast<uint16_t>(c.width + 1u);
  }
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
  end_upload();
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

void FeatureServer::end_upload() {
  staged_.filled[0] = staged_.filled[1] = 0;
  info_.staged = 0;
}

ConfigField FeatureServer::set_config(const uint8_t* buf, size_t len) {
  DeviceConfig c{};
  ConfigField r = parse_config(buf, len, c);
  if (r == ConfigField::kOk) r = apply_and_keep(c, kConfigSetByHost);
  if (r == ConfigField::kOk && store_ != nullptr && !save_current()) {
    r = ConfigField::kStore;  // in force until reboot, but not persisted
  }
  end_upload();  // applied or not, the next upload starts clean
  info_.config_status = static_cast<uint8_t>(r);
  return r;
}

ConfigField FeatureServer::set_lens(const uint8_t* buf, size_t len) {
  LensChunk c{};
  ConfigField r = ConfigField::kMalformed;
  if (decode_lens_chunk(buf, len, c).ok()) {
    // A select reads the tables in force; a piece goes to the staging.
    r = store_lens_chunk(c.count == 0 ? lens_ : staged_, c) ? ConfigField::kOk : ConfigField::kLens;
  }
  info_.lens_status = static_cast<uint8_t>(r);
  info_.staged = static_cast<uint8_t>((staged_.filled[0] != 0 ? 1u : 0u) | (staged_.filled[1] != 0 ? 2u : 0u));
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

}  // namespace lumavel::app
