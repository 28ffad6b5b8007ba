// The double twin of firmware/core/velocity_fusion.hpp (read the core's header
// for what it does and why).
#pragma once
#include <cstdint>

#include "lumavel/host/float_time_of_flight.hpp"

namespace lumavel::host {

struct FloatFusionInput {
  double dt = 0;              // s
  double v_differential = 0;  // m/s
  double observer_tau = 0;    // s
  bool direct = false;
  double v_direct = 0;
  double residual = 0;        // [0, 1]
  const FloatTofResult* tof = nullptr;
  double y = 0;               // m
  double baseline = 0;        // m
  double scale_max_turn = 0;  // rad (the core's FusionInput::scale_max_turn)
  bool against_images = false;  // (the core's)
  int image_direction = 0;      // (the core's)
};

struct FloatFusionOutput {
  double v = 0;
  bool used_tof = false;
};

class FloatVelocityFusion {
 public:
  void reset() { *this = FloatVelocityFusion{}; }
  void restart() {
    started_ = false;
    direct_seen_ = false;
    measured_us_ = 0;
    since_start_us_ = 0;
    have_direct_ = false;
    failed_ = false;
    coast_frames_ = -1;
  }
  FloatFusionOutput update(const FloatFusionInput& in);
  double v() const { return v_; }
  double scale() const { return scale_; }
  bool differential_failed() const { return failed_; }  // (the core's comment)

 private:
  bool started_ = false;
  bool direct_seen_ = false;  // (the core's)
  double v_ = 0, accel_ = 0, residual_ = 0, tof_inflation_ = 1;
  double move_accel_ = 0;  // the rate smoothed faster, for the window's move (the core's comment)
  double scale_ = 1, scale_var_ = 0;
  bool scale_started_ = false;
  // How long the observer has measured without a hold: counted as the core
  // counts it (whole microseconds), so that both gate the same frames.
  int64_t measured_us_ = 0;
  int64_t since_start_us_ = 0;  // measured time since the output (re)started (the core's units)
  double half_ = 0;                          // the observer at half its time constant (m/s)
  double prev_direct_ = 0, direct_var_ = 0;  // the direct values' scatter (m/s, (m/s)^2)
  bool have_direct_ = false;
  bool failed_ = false;     // the differential failed against the time of flight ...
  int64_t failed_us_ = 0;   // ... this long ago (us)
  double coast_z_ = 0, coast_st2_ = 0;  // the last time of flight's value and variance ...
  int64_t coast_us_ = 0;                // ... how long ago (us) ...
  int coast_frames_ = -1;               // ... in frames (-1: none to coast on)
  double move_rate() const;
  double clean_share() const;
  double shown_move(const FloatFusionInput& in, double moved, double tau) const;
  double lag_compensation(const FloatFusionInput& in, double dt, double out_tau);
};

}  // namespace lumavel::host
