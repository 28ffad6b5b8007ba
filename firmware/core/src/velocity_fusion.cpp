#include "lumavel/core/velocity_fusion.hpp"

#include <algorithm>

#include "lumavel/core/fusion_params.hpp"
#include "lumavel/core/imath.hpp"

namespace lumavel {
namespace {

using namespace params;

constexpr int64_t kResidualMinSpeedQ16 = fx::q_of(kFusionResidualMinSpeed, fx::kSpeedFrac);
constexpr int64_t kResidualGainQ16 = fx::q_of(kFusionResidualGain, 16);
constexpr int64_t kDiffFloorQ16 = fx::q_of(kFusionDiffFloor, 16);
constexpr int64_t kDiffPerResidualQ16 = fx::q_of(kFusionDiffPerResidual, 16);
constexpr int64_t kSpeedFloorQ16 = fx::q_of(kFusionSpeedFloor, fx::kSpeedFrac);
constexpr int64_t kTofFloorQ16 = fx::q_of(kFusionTofFloor, 16);
constexpr int64_t kScaleMaxResidualQ16 = fx::q_of(kFusionScaleMaxResidual, 16);
constexpr int64_t kScaleMaxChangeQ16 = fx::q_of(kFusionScaleMaxChange, 16);
constexpr int64_t kScaleWalkQ40 = fx::q_of(kFusionScaleWalk, fx::kVarFrac);  // per second
constexpr int64_t kScaleMinQ24 = fx::q_of(kFusionScaleMin, fx::kScaleFrac);
constexpr int64_t kScaleMaxQ24 = fx::q_of(kFusionScaleMax, fx::kScaleFrac);
constexpr int64_t kScaleStartVarQ40 = fx::q_of(kFusionScaleStartVar, fx::kVarFrac);
constexpr int64_t kTauNs = fx::q_of(kFusionTau * 1e9, 0);
constexpr int64_t kSlowResidualQ16 = fx::q_of(kFusionSlowResidual, 16);
constexpr int64_t kAccelTauNs = fx::q_of(kFusionAccelTau * 1e9, 0);
constexpr int64_t kAccelMaxQ16 = fx::q_of(kFusionAccelMax, fx::kAccelFrac);
constexpr int64_t kInflationGainQ16 = fx::q_of(kFusionTofInflationGain, 16);
constexpr int64_t kInflationMaxQ16 = fx::q_of(kFusionTofInflationMax, 16);
constexpr int64_t kMaxTauNs = fx::q_of(kTofMaxTau * 1e9, 0);
constexpr int64_t kOneQ16 = int64_t{1} << 16;
constexpr int kGainFrac = 24;  // the scale filter's gain, Q24
constexpr int64_t kSoftCutQ16 = fx::q_of(kFusionScaleSoftCut, 16);

int64_t abs64(int64_t v) { return v < 0 ? -v : v; }
int64_t clamp64(int64_t v, int64_t lo, int64_t hi) { return v < lo ? lo : (v > hi ? hi : v); }

}  // namespace

FusionOutput VelocityFusion::update(const FusionInput& in) {
  FusionOutput out{};
  bool sat = false;
  const TofResult& tof = *in.tof;
  const bool use_tof = tof.ok && tof.tau_ns < kMaxTauNs;
  if (in.direct && abs64(in.v_direct) > kResidualMinSpeedQ16)
    residual_ = static_cast<FracQ16>(residual_ + fx::shr_round(kResidualGainQ16 * (int64_t{in.residual} - residual_), 16));

  // The differential's scale, from its distance over the window against h,
  // where it is clean and V is steady over the window. Both conditions weigh
  // the measurement smoothly (its variance grows with their fourth power) up
  // to kFusionScaleSoftCut times their limit: an engine a bit off either way
  // of a limit then learns almost the same scale as its twin.
  if (scale_started_ && in.dt_ns > 0)
    scale_var_ = std::min<int64_t>(scale_var_ + (kScaleWalkQ40 * in.dt_ns) / 1000000000, kScaleStartVarQ40);
  const int64_t change = (abs64(accel_) * (tof.tau_ns / 1000)) / 1000000;  // Q16 m/s over tau
  const int64_t change_limit = (kScaleMaxChangeQ16 * abs64(tof.v)) >> 16;
  const int64_t q_res = fx::div_q(residual_ < 0 ? 0 : residual_, kScaleMaxResidualQ16, 16);  // Q16
  const int64_t q_change = change_limit > 0 ? fx::div_q(change, change_limit, 16) : fx::kInt32Max;
  if (use_tof && q_res < kSoftCutQ16 && q_change < kSoftCutQ16) {
    const int64_t disp = int64_t{tof.direction} * in.baseline;  // Q24 m
    const int64_t ratio = fx::div_q(in.y - tof.y_then, disp * 256, fx::kScaleFrac);  // Q32 / Q32 -> Q24
    if (ratio > 0) {
      const int64_t measured = clamp64(ratio, kScaleMinQ24, kScaleMaxQ24);
      if (!scale_started_) {
        scale_ = int32_t{1} << fx::kScaleFrac;
        scale_var_ = kScaleStartVarQ40;
        scale_started_ = true;
      }
      const int64_t sig = clamp64(tof.sig, kTofFloorQ16, kOneQ16);
      const int64_t frames = in.dt_ns > 0 ? (tof.tau_ns + in.dt_ns - 1) / in.dt_ns : 1;  // frames in the window
      const int64_t r = ((sig * sig * 4) << 8) * (frames > 1 ? frames : 1);           // Q32 -> Q40, < 2^48
      // 1 + q_res^4 + q_change^4 in Q16, < 163 with q < 3
      const int64_t qr2 = (q_res * q_res) >> 16, qc2 = (q_change * q_change) >> 16;
      const int64_t penalty = kOneQ16 + ((qr2 * qr2) >> 16) + ((qc2 * qc2) >> 16);
      const int64_t r_weighed = (r >> 16) * penalty;  // < 2^56
      // The gain in Q24 and rounded steps: the gain falls to 1e-4 and below
      // once the scale is known, where Q16 and truncation drift the scale by
      // 1e-3 an hour against the twin. var <= kFusionScaleStartVar (2^30 in
      // Q40) times 2^24 stays below 2^55.
      const int64_t k = fx::div_q(scale_var_, scale_var_ + r_weighed, kGainFrac);
      scale_ = static_cast<ScaleQ24>(
          clamp64(scale_ + fx::shr_round(k * (measured - scale_), kGainFrac), kScaleMinQ24, kScaleMaxQ24));
      scale_var_ -= fx::shr_round(scale_var_ * k, kGainFrac);
    }
  }

  const int64_t vd = fx::div_q(int64_t{in.v_differential} << fx::kScaleFrac, scale_, 0, &sat);  // Q16
  if (!in.direct) {  // nothing measured: V held
    out.v = v_;
    out.saturated = sat;
    return out;
  }
  if (!started_) {
    v_ = static_cast<SpeedQ16>(vd);
    started_ = true;
    out.v = v_;
    out.saturated = sat;
    return out;
  }
  // Uncertainties (m/s, Q16).
  const int64_t root_res = fx::isqrt32(static_cast<uint32_t>(residual_ < 0 ? 0 : residual_) << 16);  // Q16
  const int64_t speed = abs64(vd) > abs64(v_) ? abs64(vd) : abs64(v_);
  const int64_t sd = (((kDiffFloorQ16 + ((kDiffPerResidualQ16 * root_res) >> 16)) * speed) >> 16) + kSpeedFloorQ16;
  int64_t target = vd;
  if (use_tof) {
    const int64_t zc = int64_t{tof.v} + (int64_t{accel_} * tof.tau_ns) / 2000000000;
    const int64_t inflated = (int64_t{tof.sig} * fx::isqrt32(static_cast<uint32_t>(tof_inflation_))) >> 8;  // sig sqrt(n), Q16
    const int64_t rel = inflated > kTofFloorQ16 ? inflated : kTofFloorQ16;
    const int64_t st = ((rel * abs64(tof.v)) >> 16) + kSpeedFloorQ16;
    const int64_t sd2 = sd * sd, st2 = st * st;  // Q32
    const int64_t w = fx::div_q(sd2, sd2 + st2, 16);
    target = vd + ((w * (zc - vd)) >> 16);
    // How far the time of flight really scatters, seen against a clean differential.
    if (residual_ < kScaleMaxResidualQ16) {
      const int64_t nu = int64_t{tof.v} - vd;
      const int64_t g = fx::div_q(nu * nu, st2 + sd2, 16);  // Q16
      tof_inflation_ = static_cast<int32_t>(
          clamp64(tof_inflation_ + fx::shr_round(kInflationGainQ16 * (g - tof_inflation_), 16), kOneQ16, kInflationMaxQ16));
    }
  }
  // Smoothing, slower without a time of flight when the differential is doubtful.
  const int64_t teff = use_tof ? kTauNs : kTauNs + (kTauNs * residual_) / kSlowResidualQ16;
  const int64_t nv = v_ + fx::div_q((target - v_) * (in.dt_ns / 1000), (teff + in.dt_ns) / 1000, 0, &sat);
  if (in.dt_ns > 0) {
    const int64_t rate = fx::div_q((nv - v_) * 1000000000, in.dt_ns, 0, &sat);  // Q16 m/s^2
    accel_ = static_cast<AccelQ16>(clamp64(
        accel_ + fx::div_q((rate - accel_) * (in.dt_ns / 1000), (kAccelTauNs + in.dt_ns) / 1000, 0, &sat),
        -kAccelMaxQ16, kAccelMaxQ16));
  }
  v_ = fx::sat32(nv, &sat);
  out.v = v_;
  out.used_tof = use_tof;
  out.saturated = sat;
  return out;
}

}  // namespace lumavel
