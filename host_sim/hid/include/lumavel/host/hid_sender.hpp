// What `lumavel-sim run --hid SPEC` needs: one input report per estimate
// through a host link, with sequence numbers, pacing, the overrun count, and
// the feature reports served (device info; configuration get; sets refused
// without a config store, since the simulator's engine is configured from the
// recording; with a store, validated sets are accepted and persisted there,
// as on a device, while the running engine keeps the recording's configuration).
#pragma once
#include <chrono>
#include <cstdint>
#include <memory>
#include <string>

#include "lumavel/app/feature_server.hpp"
#include "lumavel/hal/config_store.hpp"
#include "lumavel/hal/report_link.hpp"
#include "lumavel/protocol/reports.hpp"

namespace lumavel::host {

// Quantises an estimate in physical units to the report's fixed-point
// formats (round to nearest; heading wrapped into [-pi, pi)).
protocol::Measurement quantise_measurement(uint64_t t_ns, uint32_t frame_index, double v_mps,
                                           double distance_m, double heading_rad, uint16_t status,
                                           double gyro_offset_radps = 0);

struct HidSenderOptions {
  int first_wait_ms = 30000;  // how long the first report waits for a host to read
  int wait_ms = 20;           // then, per report, before it counts as an overrun
  int min_interval_us = 1000; // pacing: at most one report per ms (full-speed HID)
};

class HidSender {
 public:
  // With `store`, configuration sets that pass the codec's checks are accepted
  // and saved there, and the stored configuration (if any) is served from the start.
  HidSender(std::unique_ptr<hal::ReportLink> link, const HidSenderOptions& options = {},
            std::unique_ptr<hal::ConfigStore> store = nullptr);
  // The recording's working resolution: the configuration served (and the info
  // report's resolution) unless the store holds a valid configuration.
  void set_resolution(uint16_t width, uint16_t height);
  // Sends one report; false if the host did not take it in time (counted as an overrun).
  bool send(uint64_t t_ns, double v_mps, double distance_m, double heading_rad, uint16_t status,
            double gyro_offset_radps = 0);
  void poll();  // serves pending feature requests
  uint32_t sent() const { return sent_; }
  uint16_t overruns() const { return overruns_; }

 private:
  std::unique_ptr<hal::ReportLink> link_;
  HidSenderOptions opt_;
  std::unique_ptr<hal::ConfigStore> store_;
  bool accept_ = false;  // read by the FeatureServer apply hook: host sets allowed
  app::FeatureServer features_;
  uint32_t frame_ = 0;
  uint32_t sent_ = 0;
  uint16_t overruns_ = 0;
  std::chrono::steady_clock::time_point last_{};
};

}  // namespace lumavel::host

namespace lumavel::host {
// Options suited to a link spec: no pacing for `file:` (nobody reads live).
HidSenderOptions hid_sender_options_for(const std::string& spec);
}  // namespace lumavel::host
