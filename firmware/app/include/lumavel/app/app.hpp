// The firmware application: the main loop behind the HAL, the same code on
// every board and in the host build. Integer only, fixed memory (the frame
// buffers are members sized by the core's capacities), no heap.
//
// Per frame: kick the watchdog, capture a stereo pair, push the gyro samples
// of the interval (up to the first one at or after the frame time), step the
// estimator, send the measurement report, serve feature requests.
// Configuration (boot from the store or defaults, get/set from the host) is
// the FeatureServer (feature_server.hpp); the app adds the camera check, the estimator
// and the mailbox (feature reports sent as input chunks).
#pragma once
#include <cstddef>
#include <cstdint>

#include "lumavel/app/feature_server.hpp"
#include "lumavel/core/estimator.hpp"
#include "lumavel/core/limits.hpp"
#include "lumavel/hal/camera.hpp"
#include "lumavel/hal/clock.hpp"
#include "lumavel/hal/config_store.hpp"
#include "lumavel/hal/gyro.hpp"
#include "lumavel/hal/report_link.hpp"
#include "lumavel/hal/watchdog.hpp"
#include "lumavel/protocol/device_config.hpp"
#include "lumavel/protocol/reports.hpp"

namespace lumavel::app {

struct Hal {
  hal::StereoCamera& camera;
  hal::Gyro& gyro;
  hal::Clock& clock;
  hal::ReportLink& link;
  hal::ConfigStore& store;
  hal::Watchdog& watchdog;
};

struct Board {
  const char* name;                 // DeviceInfo board name (<= 16 characters)
  protocol::DeviceConfig defaults;  // used when the store is empty or refused
};

struct Counters {
  uint32_t frames;           // frames stepped
  uint16_t overruns;         // frames dropped (timestamp gaps + capture errors), saturating
  uint32_t capture_errors;
  uint32_t reports_dropped;  // link refused an input report
  uint32_t gyro_samples;
  uint32_t feature_requests;
  uint64_t max_frame_ns;     // longest capture-to-report time seen (Clock), diagnostics only
};

enum class RunState : uint8_t { kFrame, kSkipped, kEnd, kUnconfigured };

class App {
 public:
  App(const Hal& hal, const Board& board);
  App(const App&) = delete;
  App& operator=(const App&) = delete;

  // Loads the stored configuration, validates it and falls back to the
  // board's defaults. False if neither configures the estimator.
  bool start();
  // One frame. kEnd when the camera has no more frames (recordings).
  RunState run_once();
  // Until kEnd or kUnconfigured.
  void run();

  const Counters& counters() const { return counters_; }
  const protocol::DeviceConfig& device_config() const { return features_.config(); }
  protocol::ConfigSource config_source() const {
    return static_cast<protocol::ConfigSource>(features_.info().config_source);
  }
  protocol::ConfigField config_status() const {
    return static_cast<protocol::ConfigField>(features_.info().config_status);
  }
  const Estimator& estimator() const { return estimator_; }
  // The lens tables in force.
  const protocol::LensTables& lens_tables() const { return features_.lens(); }

  // Feature requests (ReportLink::FeatureHandler). Public for unit tests.
  size_t handle_feature(uint8_t id, bool is_set, uint8_t* buf, size_t len, size_t cap);

 private:
  static protocol::ConfigField apply_hook(void* ctx, const protocol::DeviceConfig& c,
                                          const EdgeOffsetQ15* const lens[2]);
  protocol::ConfigField apply(const protocol::DeviceConfig& c, const EdgeOffsetQ15* const lens[2]);
  void push_gyro_until(uint64_t t_ns);
  void count_gap(uint64_t t_ns);
  void send_measurement(const Estimate& e);
  void send_mailbox();
  static size_t feature_trampoline(void* ctx, uint8_t id, bool is_set, uint8_t* buf, size_t len,
                                   size_t cap);

  Hal hal_;
  Board board_;
  Estimator estimator_{};
  FeatureServer features_;
  uint16_t width_ = 0;   // of the running configuration
  uint16_t height_ = 0;
  uint32_t frame_period_us_ = 0;
  bool configured_ = false;
  Counters counters_{};
  uint16_t seq_ = 0;
  bool have_frame_ = false;
  uint64_t last_frame_ns_ = 0;
  bool have_gyro_ = false;
  uint64_t last_gyro_ns_ = 0;
  uint8_t mailbox_id_ = 0;  // feature report to send as input chunks, 0 = none
  uint8_t mailbox_tag_ = 0; // the request's tag, echoed in every chunk
  alignas(4) uint8_t frame_[2][kMaxColumns * kMaxRows]{};  // word-aligned rows help the column sums
};

}  // namespace lumavel::app
