// The fused velocity: the differential observer (paper eq. 9, instantaneous,
// exact where the stereo disparity is small against the kernels) and the time
// of flight (depth-free, but a mean over its window), each weighted by how far
// it can be trusted at this moment.
//
// - The differential's uncertainty comes from itself: the least-squares
//   residual of its kernels (velocity_observer.hpp). Where near texture makes
//   the stereo difference alias, the kernels disagree and the residual rises;
//   on a clean scene it is near zero and the output is the differential's.
//   The uncertainty of the learned scale it is divided by adds to it (in
//   quadrature): an unsettled scale leaves more weight to the time of flight.
// - The time of flight's uncertainty is its match's timing uncertainty over
//   tau (time_of_flight.hpp), never below kFusionTofFloor. Its window mean
//   lags a changing V by tau / 2, which is added back from the fused V's own
//   rate of change (followed faster where the differential is clean).
// - The differential's scale (its distance over the window against h) is
//   learned where the differential is clean, as a slow random walk, and the
//   differential is divided by it: a consistent bias, e.g. from a finite
//   baseline on broadband texture, goes away even where no time of flight is
//   found for a while. Only over a window the observer measured throughout:
//   over a hold (low texture, a gap, no light) the differential's integral
//   stands still or carries the held V, which would read as a scale.
// - The observer's first-order V lags a ramp by tau_obs A: added back as
//   twice the gap to the same observer at half its time constant, where that
//   stands out of its noise (fusion_params.hpp, kFusionLagSigmas), scaled to
//   the ramp's two other lags, the direct values' half interval and the
//   output's own smoothing: (tau_obs + dt/2 + kFusionTau) A.
// - Without a time of flight (standstill, too slow for the history, turning,
//   reversing, lost), the output follows the differential, more slowly the
//   less it can be trusted; the caller flags the frame (kStatusNoTof). Never
//   more slowly than the time since the output (re)started: until then it is
//   the mean of the values since (a start is one noisy value, not a prior).
// - Where the differential cannot see motion (low texture), V is held, as the
//   observer holds it.
//
// Plain data in and out, integer only. Its double twin is
// host_sim/reference/src/float_velocity_fusion.cpp.
#pragma once
#include <cstdint>

#include "lumavel/core/fixed.hpp"
#include "lumavel/core/time_of_flight.hpp"

namespace lumavel {

struct FusionInput {
  int64_t dt_ns;
  SpeedQ16 v_differential;  // the observer's V
  uint32_t observer_tau_us;  // the observer's time constant (its lag on a ramp)
  bool direct;              // the observer measured this interval ...
  SpeedQ16 v_direct;        // ... this value ...
  FracQ16 residual;         // ... with this residual ratio
  const TofResult* tof;     // this frame's time of flight (ok or not)
  TravelQ16Ns y;            // integral of v_differential (TofFrame::y of this frame)
  LengthQ24 baseline;
  AngleQ28 scale_max_turn;  // the window's turn at which a scale measurement is weighed as at its limit (kFusionScaleMaxTurnSigma)
  bool against_images;      // the output runs against the images' direction of travel (ImageDirection::against)
  int8_t image_direction;   // the images' direction of travel (ImageDirection::direction), 0 unknown
};

struct FusionOutput {
  SpeedQ16 v;
  bool used_tof;   // the time of flight entered this frame's estimate
  bool saturated;
};

class VelocityFusion {
 public:
  void reset() { *this = VelocityFusion{}; }
  // After a break (gap, no light): V is held until the next update, which
  // starts again from the differential; the learned scale, residual and
  // inflation are kept.
  void restart() {
    started_ = false;
    direct_seen_ = false;
    measured_us_ = 0;
    since_start_us_ = 0;
    have_direct_ = false;
    failed_ = false;
    coast_frames_ = -1;
  }
  FusionOutput update(const FusionInput& in);
  // The fused V: held over frames without an update (no light, gaps, low
  // texture) and before the first one (0).
  SpeedQ16 v() const { return v_; }
  ScaleQ24 scale() const { return scale_; }
  // The differential pointed against the last time of flight and has not agreed since (kFusionFailedHold).
  bool differential_failed() const { return failed_; }
  // A differential value divided by the learned scale.
  SpeedQ16 rescaled(SpeedQ16 v_differential) const {
    return fx::sat32(fx::shr_round(int64_t{v_differential} * inv_scale_, fx::kScaleFrac));
  }

 private:
  bool started_ = false;
  bool direct_seen_ = false;       // the observer has measured since the (re)start
  SpeedQ16 v_ = 0;
  AccelQ16 accel_ = 0;
  AccelQ16 move_accel_ = 0;        // the same rate smoothed faster, for the window's move where the differential is clean
  FracQ16 residual_ = 0;           // tracked residual ratio of the differential
  int32_t tof_inflation_ = int32_t{1} << 16;  // Q16, >= 1: the time of flight's variance factor
  int64_t measured_us_ = 0;        // how long the observer has measured without a break (us, capped)
  int64_t since_start_us_ = 0;     // measured time since the output (re)started, capped
  SpeedQ16 half_ = 0;              // the observer at half its time constant
  SpeedQ16 prev_direct_ = 0;       // the last direct value, for the scatter ...
  int64_t direct_var_ = 0;         // ... of their differences (Q32 (m/s)^2, smoothed over kFusionAccelTau)
  bool have_direct_ = false;
  bool failed_ = false;            // the differential failed against the time of flight ...
  int64_t failed_us_ = 0;          // ... this long ago (us, capped)
  int64_t coast_z_ = 0;            // the last time of flight's value (Q16, moved to the present) ...
  int64_t coast_st2_ = 0;          // ... its variance (Q32) ...
  int64_t coast_us_ = 0;           // ... how long ago (us, capped) ...
  int32_t coast_frames_ = -1;      // ... in frames since (-1: none to coast on)
  // The rate the window is moved to the present by (kFusionMoveAccelTau, fusion_params.hpp).
  int64_t move_rate() const;
  // How clean the differential is for the move: 1 to 0 over kFusionScaleMaxResidual..kFusionMoveAccelResidual.
  int64_t clean_share() const;
  // That move (A tau / 2, Q16), held where the differential is clean to what the observer shows.
  int64_t shown_move(const FusionInput& in, int64_t moved, int64_t tau_us) const;
  // The observer's lag on a ramp, with what the output's smoothing (time constant out_tau_us) adds to it.
  int64_t lag_compensation(const FusionInput& in, int64_t dt_us, int64_t out_tau_us);
  void learn_scale(const FusionInput& in, int64_t dt_us, int64_t q_res, int64_t q_change, int64_t q_short, int64_t q_turn);

  ScaleQ24 scale_ = int32_t{1} << fx::kScaleFrac;
  ScaleQ24 inv_scale_ = int32_t{1} << fx::kScaleFrac;  // 1 / scale_
  VarQ40 scale_var_ = 0;
  bool scale_started_ = false;
};

}  // namespace lumavel
