// Device-side handling of the feature reports, ready to pass to
// hal::ReportLink::poll_features: device info (get), configuration (get/set:
// CRC, version, ranges, then the application's apply hook, then the store).
// Optional helper; integer only, no heap.
#pragma once
#include <cstddef>
#include <cstdint>

#include "lumavel/hal/config_store.hpp"
#include "lumavel/protocol/device_config.hpp"
#include "lumavel/protocol/reports.hpp"

namespace lumavel::protocol {

class FeatureServer {
 public:
  // Applies a range-checked configuration (e.g. rebuilds the estimator).
  // Returns kOk, or kEstimator if the estimator refused it (nothing changes then).
  using ApplyFn = ConfigField (*)(void* ctx, const DeviceConfig& cfg);

  // `identity` gives firmware version, board and capacities; the working
  // resolution and config status/source are kept up to date by the server.
  FeatureServer(const DeviceInfo& identity, hal::ConfigStore* store, ApplyFn apply, void* ctx);

  // At boot: the stored configuration if it decodes and applies, else
  // `defaults` (which must apply). Returns the status of `defaults` if even that fails.
  ConfigField boot(const DeviceConfig& defaults);

  // hal::ReportLink::FeatureHandler; ctx is the FeatureServer.
  static size_t handle(void* ctx, uint8_t id, bool is_set, uint8_t* buf, size_t len, size_t cap);

  // Set from the host: decode, validate, apply, persist. Returns the outcome,
  // also reported in DeviceInfo.config_status.
  ConfigField set_config(const uint8_t* buf, size_t len);

  const DeviceConfig& config() const { return config_; }
  const DeviceInfo& info() const { return info_; }

 private:
  ConfigField apply_and_keep(const DeviceConfig& c, uint8_t source);

  DeviceInfo info_;
  DeviceConfig config_{};
  hal::ConfigStore* store_;
  ApplyFn apply_;
  void* ctx_;
};

}  // namespace lumavel::protocol
