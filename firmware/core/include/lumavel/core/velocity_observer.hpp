// The velocity observer (paper eq. 9), discretised per frame interval.
//
// Between frames n-1 and n the measurement model is, for every kernel k,
//   dM_k = M_k(n) - M_k(n-1) = d * Sbar_k / h + dtheta * Rbar_k
// with d = V dt the distance travelled, Sbar/Rbar the trapezoid means of S and
// R over the two frames and dtheta the integrated gyro. The innovation of eq. 9
// with a deadbeat B-hat (L1 -> B reset every frame) projected on dF/dx gives
// the least-squares distance over the kernels:
//   d = h * sum_k (dM_k - dtheta Rbar_k) Sbar_k / sum_k Sbar_k^2
// and the V-hat update of eq. 9 with l2 normalised by |dF/dx|^2 becomes
//   V <- V + g (d/dt - V),  g = dt / (tau + dt)          (implicit Euler)
// so V's error decays with time constant tau whatever the texture contrast,
// resolution or frame rate. The observer starts from the first direct value
// and, until tau has passed, averages the values that came since: the time
// constant is then the time since the start plus kObserverStartPrior tau.
//
// Finite-baseline correction: for texture of spatial frequency k the mean
// M = (F0 + F1)/2 is attenuated by cos(kh/2) while S = F1 - F0 is 2 sin(kh/2)/k
// times dF/dx, so dM = (d/h) S x/tan(x), x = kh/2: V comes out low by about
// x^2/3 (-8.6 % for the paper's 0.5 m sinusoid at h = 8 cm). Each kernel's
// x is measured as half the phase difference between the cameras
// (measurement.hpp) and the least squares uses A_k = Sbar_k x_k / tan(x_k).
// (A second-order version through kappa^3 d3F/dtheta3 over-corrected by 2 %:
// its own inputs carry the same finite-baseline factors.)
//
// Finite-step correction: the frame-to-frame difference is as finite as the
// stereo one. Over a step d, dM carries sin(kd/2) and the trapezoid Sbar
// cos(kd/2), so dM / A = tan(y) / x and h dM / A = d tan(y) / y, y = k d / 2
// = x d / h (the same depth divides both: y needs no depth). At 8 cm and 60 Hz
// that is +1 % at 5 m/s past a car and +5-10 % at 12 m/s. Each innovation is
// scaled by y / tan(y) with y from the solution itself: two evaluations of
// that map and Aitken's extrapolation reach its fixed point (one evaluation
// over-corrects by half the bias again: the first d is the biased one).
// (y from the observer's V instead gave the same figures for one evaluation,
// but split the day soak's twin on 10 frames: it was not kept.)
#pragma once
#include <cstdint>

#include "lumavel/core/estimator_params.hpp"
#include "lumavel/core/fixed.hpp"
#include "lumavel/core/measurement.hpp"

namespace lumavel {

struct ObserverInput {
  const StereoMeasurement* prev;
  const StereoMeasurement* cur;
  int64_t dt_ns;
  AngleQ28 dtheta;  // integrated gyro over the interval
  LengthQ24 baseline;
  uint32_t tau_us;
  ValueQ28 low_texture;
  bool baseline_correction;
};

struct ObserverOutput {
  SpeedQ16 v;
  SpeedQ16 v_direct;
  ValueQ28 texture;
  // How far the kernels disagree: the least-squares residual over the squared
  // innovation, in [0, 1]. Near 0 where every kernel sees the same distance;
  // it rises where near texture aliases the stereo difference (a measure of
  // the direct value's trust, used by velocity_fusion.hpp).
  FracQ16 residual;
  bool updated;      // false: low texture, V held
  bool saturated;
  bool converging;
};

// One step of the observer's law over an interval: implicit Euler of
// dV/dt = (v_direct - V) / tau, V + (v_direct - V) dt / (tau + dt) (Q16 m/s;
// dt below 2^31 us so that the product stays in int64).
inline SpeedQ16 observer_step(SpeedQ16 v, SpeedQ16 v_direct, int64_t dt_us, int64_t tau_us, bool* sat) {
  return fx::sat32(int64_t{v} + fx::div_q((int64_t{v_direct} - v) * dt_us, tau_us + dt_us, 0, sat), sat);
}

class VelocityObserver {
 public:
  void reset();
  // Next measurement re-initialises V directly; V is held until then.
  void restart() {
    started_ = false;
    since_start_us_ = 0;
  }
  ObserverOutput update(const ObserverInput& in);
  // An interval that cannot be used (its rotation unknown): V held, no update.
  ObserverOutput hold() const {
    ObserverOutput o{};
    o.v = v_;
    o.converging = converging_now();
    return o;
  }
  SpeedQ16 v() const { return v_; }
  // The time constant of the last update (us, >= 1): tau_us, or less while
  // the start was younger than tau (kObserverStartPrior). The fusion's lag
  // correction takes the same.
  uint32_t time_constant_us() const { return tau_now_us_; }
  // Not started, or started less than kConvergingTaus (3) time constants ago.
  bool converging_now() const {
    return !started_ || since_start_us_ < ((kConvergingTausQ4 * tau_us_) >> 4);
  }

 private:
  // The converging time in time constants, Q4 (exact for whole and half values).
  static constexpr int64_t kConvergingTausQ4 = fx::q_of(params::kConvergingTaus, 4);
  static_assert(fx::q_of(params::kConvergingTaus, 30) == kConvergingTausQ4 << 26, "exact in Q4");
  static constexpr int64_t kStartPriorQ16 = fx::q_of(params::kObserverStartPrior, 16);
  // The time since the start plus kObserverStartPrior tau, within [1, tau] us.
  static uint32_t young_time_constant_us(int64_t since_start_us, uint32_t tau_us) {
    const int64_t young_us = since_start_us + ((int64_t{tau_us} * kStartPriorQ16) >> 16);
    return static_cast<uint32_t>(young_us < 1 ? 1 : young_us < tau_us ? young_us : tau_us);
  }
  SpeedQ16 v_ = 0;
  bool started_ = false;
  int64_t since_start_us_ = 0;  // in the whole microseconds each step takes
  uint32_t tau_now_us_ = 1;
  uint32_t tau_us_ = 0;  // as configured
};

}  // namespace lumavel
