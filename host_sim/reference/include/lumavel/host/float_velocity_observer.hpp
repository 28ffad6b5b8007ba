// The double twin of firmware/core/velocity_observer.hpp (read the core's
// header for the model, the least squares over kernels and the
// finite-baseline correction).
#pragma once
#include <algorithm>
#include <cstdint>

#include "lumavel/core/estimator_params.hpp"
#include "lumavel/host/float_measurement.hpp"

namespace lumavel::host {

// One step of the observer's law (velocity_observer.hpp): V + (v_direct - V) dt / (tau + dt).
inline double observer_step(double v, double v_direct, double dt, double tau) { return v + (v_direct - v) * dt / (tau + dt); }

struct FloatObserverInput {
  const FloatStereoMeasurement* prev = nullptr;
  const FloatStereoMeasurement* cur = nullptr;
  double dt = 0;        // s
  uint64_t dt_ns = 0;   // the same interval in ns: the converging time adds these, as the core does
  double dtheta = 0;    // integrated gyro over the interval, rad
  double baseline = 0;  // m
  double tau = 0;       // s
  double low_texture = 0;
  bool baseline_correction = false;
};

struct FloatObserverOutput {
  double v = 0;         // m/s
  double v_direct = 0;  // m/s, 0 when not updated
  double texture = 0;   // rms over kernels of F1 - F0, weaker frame of the interval
  double residual = 0;  // the kernels' disagreement, [0, 1]
  bool updated = false;  // false: low texture, V held
  bool saturated = false;  // the step passed what the core's format holds (8 baselines a frame), as the core
};

class FloatVelocityObserver {
 public:
  // tau_us: the configured time constant in whole microseconds, as the core
  // has it, so that both engines stop converging on the same frame.
  explicit FloatVelocityObserver(uint32_t tau_us = 0);
  // Next measurement re-initialises V directly; V is held until then.
  void restart() {
    started_ = false;
    since_start_us_ = 0;
  }
  FloatObserverOutput update(const FloatObserverInput& in);
  // An interval that cannot be used (its rotation unknown): V held, no update.
  FloatObserverOutput hold() const {
    FloatObserverOutput o;
    o.v = v_;
    return o;
  }
  double v() const { return v_; }
  // The time constant of the last update (s): tau, or less while the start
  // was younger than tau (the core's time_constant_us(), its time in the
  // whole microseconds of each step).
  double time_constant() const { return tau_now_; }
  // Not started, or started less than kConvergingTaus time constants ago.
  bool converging_now() const { return !started_ || since_start_us_ < converging_us_; }

 private:
  // The time since the start plus kObserverStartPrior tau, within [1 us, tau] (s).
  static double young_time_constant(int64_t since_start_us, double tau) {
    return std::min(tau, std::max(static_cast<double>(since_start_us) * 1e-6 + params::kObserverStartPrior * tau, 1e-6));
  }
  double v_ = 0;
  bool started_ = false;
  int64_t since_start_us_ = 0;  // in the whole microseconds of each step, as the core counts
  double tau_now_ = 1e-6;
  int64_t converging_us_ = 0;
};

}  // namespace lumavel::host
