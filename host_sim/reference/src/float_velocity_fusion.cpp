// Twin of firmware/core/src/velocity_fusion.cpp.
#include "lumavel/host/float_velocity_fusion.hpp"

#include <algorithm>
#include <cmath>

#include "lumavel/core/fusion_params.hpp"
#include "lumavel/host/float_velocity_observer.hpp"

namespace lumavel::host {

using namespace params;

FloatFusionOutput FloatVelocityFusion::update(const FloatFusionInput& in) {
  FloatFusionOutput out;
  const FloatTofResult& tof = *in.tof;
  const bool use_tof = tof.ok && tof.tau_ns < kTofMaxTau * 1e9;
  const double dt = std::min(in.dt, 2.147483647);  // as the core: below 2^31 ns
  // The time the observer has measured without a hold (the core's comment).
  const int64_t dt_us = dt > 0 ? std::llround(dt * 1e9) / 1000 : 0;
  const int64_t tau_us = use_tof ? static_cast<int64_t>(tof.tau_ns) / 1000 : 0;
  measured_us_ = in.direct ? std::min<int64_t>(measured_us_ + dt_us, int64_t{1} << 31) : 0;
  const bool whole_window = measured_us_ >= tau_us + dt_us;
  // (ramped in from kFusionResidualMinSpeed to kFusionResidualFullSpeed: the core's comment)
  const double ramp = std::clamp((std::fabs(in.v_direct) - kFusionResidualMinSpeed) /
                                     (kFusionResidualFullSpeed - kFusionResidualMinSpeed), 0.0, 1.0);
  if (in.direct && ramp > 0) residual_ += kFusionResidualGain * ramp * (in.residual - residual_);
  // The scale's measurement weighed by how clean and how steady (the core's comment).
  if (scale_started_ && dt > 0) scale_var_ = std::min(scale_var_ + kFusionScaleWalk * dt, kFusionScaleStartVar);
  const double change = std::fabs(accel_) * tof.tau_ns * 1e-9;
  const double change_limit = kFusionScaleMaxChange * std::fabs(tof.v);
  const double q_res = std::max(residual_, 0.0) / kFusionScaleMaxResidual;
  const double q_change = change_limit > 0 ? change / change_limit : HUGE_VAL;
  const double q_short = kFusionScaleShortFrames * static_cast<double>(dt_us) / static_cast<double>(std::max<int64_t>(tau_us, 1));
  const double q_turn = in.scale_max_turn > 0 ? tof.turn / in.scale_max_turn : 0;
  if (use_tof && whole_window && q_res < kFusionScaleSoftCut && q_change < kFusionScaleSoftCut &&
      q_short < kFusionScaleSoftCut && q_turn < kFusionScaleSoftCut) {
    const double ratio = (in.y - tof.y_then) / (tof.direction * in.baseline);
    if (ratio > 0) {
      const double measured = std::clamp(ratio, kFusionScaleMin, kFusionScaleMax);
      if (!scale_started_) {
        scale_ = 1;
        scale_var_ = kFusionScaleStartVar;
        scale_started_ = true;
      }
      const double sig = std::clamp(tof.sig, kFusionTofFloor, 1.0);
      const double frames = std::max(1.0, std::ceil(tof.tau_ns / (dt * 1e9)));
      const double penalty = 1 + std::pow(q_res, 4) + std::pow(q_change, 4) + std::pow(q_short, 4) + std::pow(q_turn, 4);
      const double k = scale_var_ / (scale_var_ + 4 * sig * sig * frames * penalty);
      scale_ = std::clamp(scale_ + k * (measured - scale_), kFusionScaleMin, kFusionScaleMax);
      scale_var_ *= 1 - k;
    }
  }
  // The output's smoothing, slowed by the residual; the differential's lag as
  // that of the output it makes alone (the core's comment).
  const double slowed_tau = kFusionTau * (1 + residual_ / kFusionSlowResidual);
  const double vd = in.v_differential / scale_ + lag_compensation(in, dt, slowed_tau);
  // The time of flight alone before the observer has measured (the core's comment).
  const bool tof_alone = !in.direct && !direct_seen_ && use_tof && tof.frames >= kTofWindowGateFrames &&
                         in.image_direction != 0 && (tof.v > 0) == (in.image_direction > 0);
  if (in.direct) direct_seen_ = true;
  if (!in.direct && !tof_alone) {  // nothing measured: V held, unless against the images (the core's comment)
    if (in.against_images) v_ -= v_ * dt / (kFusionTau + dt);
    out.v = v_;
    return out;
  }
  if (!started_ && !tof_alone) {
    v_ = vd;
    started_ = true;
    out.v = v_;
    return out;
  }
  const double speed = std::max(std::fabs(vd), std::fabs(v_));
  const double sd = (kFusionDiffFloor + kFusionDiffPerResidual * std::sqrt(std::max(residual_, 0.0))) * speed +
                    kFusionSpeedFloor;
  // The differential's variance: its own and that of the scale it is divided by.
  const double held = std::min(speed, kFusionScaleTermMaxSpeed);
  const double sd2 = sd * sd + scale_var_ * held * held;
  double target = vd;
  if (use_tof) {
    const double moved = shown_move(in, move_rate() * tof.tau_ns * 1e-9 / 2, tof.tau_ns * 1e-9);
    const double zc = tof.v + moved;
    const double rel = std::max(tof.sig * std::sqrt(tof_inflation_), kFusionTofFloor);
    const double st = rel * std::fabs(tof.v) + kFusionSpeedFloor;
    const double st2 = st * st + std::pow(kFusionTofMoveShare * moved, 2);  // the move's own uncertainty
    // Against its direction now, where that is clear (the core's comment).
    const bool against = !tof_alone && (vd > 0) != (zc > 0) && std::fabs(vd) > kFusionAgainstSigmas * sd &&
                         zc * zc > kFusionAgainstSigmas * kFusionAgainstSigmas * st2;
    failed_ = against;
    failed_us_ = 0;
    const double w = against || tof_alone ? 1.0 : sd2 / (sd2 + st2);
    target = vd + w * (zc - vd);
    coast_z_ = zc;
    coast_st2_ = st2;
    coast_us_ = 0;
    coast_frames_ = 0;
    if (residual_ < kFusionScaleMaxResidual && !against && !tof_alone) {
      const double g = (tof.v - vd) * (tof.v - vd) / (st2 + sd2);
      tof_inflation_ = std::clamp(tof_inflation_ + kFusionTofInflationGain * (g - tof_inflation_), 1.0,
                                  kFusionTofInflationMax);
    }
  }
  if (!use_tof) {  // a track held through a miss (the core's comment)
    if (tof.held && coast_frames_ >= 0 && !failed_) {
      coast_us_ = std::min<int64_t>(coast_us_ + dt_us, int64_t{1} << 31);
      ++coast_frames_;
      const double zc = coast_z_ + move_rate() * static_cast<double>(coast_us_) * 1e-6;
      const double grow = kFusionCoastSigmaGrowth * (coast_frames_ + 1);
      const double st2 = coast_st2_ * grow * grow;
      target = vd + sd2 / (sd2 + st2) * (zc - vd);
    } else {
      coast_frames_ = -1;
    }
  }
  if (!use_tof && failed_) {  // held until it agrees again (the core's comment)
    failed_us_ = std::min<int64_t>(failed_us_ + dt_us, int64_t{1} << 31);
    const bool agrees = (vd > 0) == (v_ > 0) || std::fabs(vd) <= kFusionAgainstSigmas * sd;
    if (agrees || failed_us_ > static_cast<int64_t>(kFusionFailedHold * 1e6)) {
      failed_ = false;
    } else {
      out.v = v_;
      return out;
    }
  }
  if (!started_) {  // (a start on the time of flight alone)
    v_ = target;
    started_ = true;
    out.v = v_;
    out.used_tof = true;
    return out;
  }
  since_start_us_ = std::min<int64_t>(since_start_us_ + dt_us, int64_t{1} << 31);
  const double teff = std::min(use_tof ? kFusionTau : slowed_tau, static_cast<double>(since_start_us_) * 1e-6);
  const double nv = v_ + (target - v_) * dt / (teff + dt);
  if (dt > 0) {
    accel_ = std::clamp(accel_ + ((nv - v_) / dt - accel_) * dt / (kFusionAccelTau + dt), -kFusionAccelMax,
                        kFusionAccelMax);
    move_accel_ = std::clamp(move_accel_ + ((nv - v_) / dt - move_accel_) * dt / (kFusionMoveAccelTau + dt),
                             -kFusionAccelMax, kFusionAccelMax);
  }
  v_ = nv;
  out.v = v_;
  out.used_tof = use_tof;
  return out;
}

// The observer's lag on a ramp, added back where it stands out of its noise
// and no further than the observer shows it (the core's comments).
double FloatVelocityFusion::clean_share() const {
  if (failed_) return 0;  // (the core's comment)
  return std::clamp((kFusionMoveAccelResidual - residual_) / (kFusionMoveAccelResidual - kFusionScaleMaxResidual), 0.0, 1.0);
}

double FloatVelocityFusion::move_rate() const { return accel_ + clean_share() * (move_accel_ - accel_); }

double FloatVelocityFusion::shown_move(const FloatFusionInput& in, double moved, double tau) const {
  // Held to what the observer shows in the measure that the differential is clean (the core's comment).
  const double share = clean_share();
  if (share <= 0 || in.observer_tau <= 0) return moved;
  const double cap = std::clamp(half_ - in.v_differential, -128.0, 128.0) * tau / in.observer_tau;
  const double held = (cap > 0) != (moved > 0) ? 0 : (std::fabs(cap) < std::fabs(moved) ? cap : moved);
  return moved + share * (held - moved);
}

double FloatVelocityFusion::lag_compensation(const FloatFusionInput& in, double dt, double out_tau) {
  if (!in.direct || dt <= 0) return 0;
  if (!have_direct_) {
    half_ = in.v_differential;
    prev_direct_ = in.v_direct;
    have_direct_ = true;
    return 0;
  }
  const double dv = std::clamp(in.v_direct - prev_direct_, -128.0, 128.0);
  direct_var_ += (dv * dv - direct_var_) * dt / (kFusionAccelTau + dt);
  prev_direct_ = in.v_direct;
  const double c = std::clamp(accel_ * in.observer_tau, -128.0, 128.0);
  const double floor_sd = kFusionDiffFloor * std::min(std::fabs(in.v_differential), 128.0);
  const double var_c = direct_var_ / 2 * dt / (2 * kFusionAccelTau + dt) + floor_sd * floor_sd;
  const double den = c * c + kFusionLagSigmas * kFusionLagSigmas * var_c;
  const double weighed = den > 0 ? c * c / den * c : 0;
  half_ = observer_step(half_, in.v_direct, dt, in.observer_tau / 2);
  const double shown = std::clamp(2 * (half_ - in.v_differential), -128.0, 128.0);
  if ((weighed > 0) != (shown > 0) || weighed == 0 || shown == 0) return 0;
  const double lag = std::fabs(weighed) < std::fabs(shown) ? weighed : shown;
  // The same ramp lags twice more downstream: the half interval and the output's smoothing.
  return lag * (in.observer_tau + dt / 2 + out_tau) / in.observer_tau;
}

}  // namespace lumavel::host
