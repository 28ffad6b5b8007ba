#include "lumavel/core/velocity_fusion.hpp"

#include <algorithm>

#include "lumavel/core/fusion_params.hpp"
#include "lumavel/core/imath.hpp"
#include "lumavel/core/velocity_observer.hpp"

namespace lumavel {
namespace {

using namespace params;

constexpr int64_t kResidualMinSpeedQ16 = fx::q_of(kFusionResidualMinSpeed, fx::kSpeedFrac);
constexpr int64_t kResidualFullSpeedQ16 = fx::q_of(kFusionResidualFullSpeed, fx::kSpeedFrac);
static_assert(kResidualMinSpeedQ16 < kResidualFullSpeedQ16, "the residual's ramp needs a width");
constexpr int64_t kResidualGainQ16 = fx::q_of(kFusionResidualGain, 16);
constexpr int64_t kDiffFloorQ16 = fx::q_of(kFusionDiffFloor, 16);
constexpr int64_t kDiffPerResidualQ16 = fx::q_of(kFusionDiffPerResidual, 16);
constexpr int64_t kSpeedFloorQ16 = fx::q_of(kFusionSpeedFloor, fx::kSpeedFrac);
constexpr int64_t kTofFloorQ16 = fx::q_of(kFusionTofFloor, 16);
constexpr int64_t kScaleMaxResidualQ16 = fx::q_of(kFusionScaleMaxResidual, 16);
constexpr int64_t kInvMaxResidualQ16 = fx::q_of(1 / kFusionScaleMaxResidual, 16);
constexpr int64_t kScaleMaxChangeQ16 = fx::q_of(kFusionScaleMaxChange, 16);
constexpr int64_t kScaleWalkPerUsQ48 = fx::q_of(kFusionScaleWalk * 1e-6, fx::kVarFrac + 8);  // per microsecond
constexpr int64_t kScaleMinQ24 = fx::q_of(kFusionScaleMin, fx::kScaleFrac);
constexpr int64_t kScaleMaxQ24 = fx::q_of(kFusionScaleMax, fx::kScaleFrac);
constexpr int64_t kScaleStartVarQ40 = fx::q_of(kFusionScaleStartVar, fx::kVarFrac);
constexpr int64_t kTauUs = fx::q_of(kFusionTau * 1e6, 0);
constexpr int64_t kSlowUsPerResidual = fx::q_of(kFusionTau * 1e6 / kFusionSlowResidual, 0);  // us per unit residual
constexpr int64_t kAccelTauUs = fx::q_of(kFusionAccelTau * 1e6, 0);
constexpr int64_t kMoveAccelTauUs = fx::q_of(kFusionMoveAccelTau * 1e6, 0);
constexpr int64_t kMoveAccelResidualQ16 = fx::q_of(kFusionMoveAccelResidual, 16);
// 1 / (kFusionMoveAccelResidual - kFusionScaleMaxResidual): the blend's slope per unit residual
constexpr int64_t kMoveBlendSlopeQ16 = fx::q_of(1 / (kFusionMoveAccelResidual - kFusionScaleMaxResidual), 16);
constexpr int64_t kHalfPerMillionQ40 = fx::q_of(0.5e-6, 40);  // A tau / 2 with tau in us
constexpr int64_t kInt31 = int64_t{1} << 31;
constexpr int64_t kAccelMaxQ16 = fx::q_of(kFusionAccelMax, fx::kAccelFrac);
constexpr int64_t kInflationGainQ16 = fx::q_of(kFusionTofInflationGain, 16);
constexpr int64_t kInflationMaxQ16 = fx::q_of(kFusionTofInflationMax, 16);
constexpr int64_t kOneQ16 = int64_t{1} << 16;
constexpr int64_t kAgainstSigmasQ16 = fx::q_of(kFusionAgainstSigmas, 16);
constexpr int64_t kAgainstSigmas2Q8 = fx::q_of(kFusionAgainstSigmas * kFusionAgainstSigmas, 8);
constexpr int64_t kMoveShareQ16 = fx::q_of(kFusionTofMoveShare, 16);
constexpr int64_t kScaleTermMaxSpeedQ16 = fx::q_of(kFusionScaleTermMaxSpeed, fx::kSpeedFrac);
static_assert(kFusionScaleTermMaxSpeed <= 64, "held speed^2 in Q16 below 2^28");
constexpr int kGainFrac = 24;  // the scale filter's gain, Q24
constexpr int64_t kSoftCutQ16 = fx::q_of(kFusionScaleSoftCut, 16);
constexpr int64_t kLagSigmas2Q8 = fx::q_of(kFusionLagSigmas * kFusionLagSigmas, 8);
constexpr int64_t kLagMaxQ16 = int64_t{1} << 23;  // speed differences held to 128 m/s: squares x a Q16 gain < 2^62
constexpr int64_t kShortFramesQ16 = fx::q_of(kFusionScaleShortFrames, 16);
constexpr int64_t kFailedHoldUs = fx::q_of(kFusionFailedHold * 1e6, 0);
constexpr int64_t kCoastGrowth = fx::q_of(kFusionCoastSigmaGrowth, 0);
static_assert(kCoastGrowth * 4 == fx::q_of(kFusionCoastSigmaGrowth, 2), "a whole factor: the variance stays exact");
static_assert(kFusionAccelMax * kTofMaxTau / 2 < 4, "the time of flight's move to the present below 2^18 in Q16: its square fits");

int64_t abs64(int64_t v) { return v < 0 ? -v : v; }

}  // namespace

FusionOutput VelocityFusion::update(const FusionInput& in) {
  FusionOutput out{};
  bool sat = false;
  const TofResult& tof = *in.tof;
  const bool use_tof = tof.ok && tof.tau_ns < kTofMaxTauNs;
  // Times in microseconds from here, in 32 bits: every division by a
  // constant is then a multiply on a 32-bit core, not a 64-bit library call.
  // A frame interval beyond 2^31 ns (2.1 s) counts as 2.1 s (the observer
  // restarts long before).
  const int64_t dt_us = in.dt_ns <= 0 ? 0 : static_cast<int64_t>(static_cast<uint32_t>(std::min<int64_t>(in.dt_ns, kInt31 - 1)) / 1000u);
  const int64_t tau_us = use_tof ? static_cast<int64_t>(static_cast<uint32_t>(tof.tau_ns) / 1000u) : 0;
  // The time the observer has measured without a hold, capped beyond any window.
  measured_us_ = in.direct ? std::min<int64_t>(measured_us_ + dt_us, kInt31) : 0;
  // Its gain ramps up from kFusionResidualMinSpeed to kFusionResidualFullSpeed:
  // with a step there, two engines a hair either side of it tracked
  // different residuals, smoothed the output differently and parted by 3 mm/s.
  const int64_t direct_speed = abs64(in.v_direct);
  if (in.direct && direct_speed > kResidualMinSpeedQ16) {
    const int64_t gain = direct_speed >= kResidualFullSpeedQ16
                             ? kResidualGainQ16
                             : fx::div_q(kResidualGainQ16 * (direct_speed - kResidualMinSpeedQ16),
                                         kResidualFullSpeedQ16 - kResidualMinSpeedQ16, 0);
    residual_ = static_cast<FracQ16>(residual_ + fx::shr_round(gain * (int64_t{in.residual} - residual_), 16));
  }

  // The differential's scale, from its distance over the window against h,
  // where it is clean, V is steady over the window and the window spans
  // frames (not a fraction of one). The conditions weigh the measurement
  // smoothly (its variance grows with their fourth power) up to
  // kFusionScaleSoftCut times their limit: an engine a bit off either way of
  // a limit then learns almost the same scale as its twin.
  if (scale_started_ && dt_us > 0)
    scale_var_ = std::min<int64_t>(scale_var_ + fx::shr_round(kScaleWalkPerUsQ48 * dt_us, 8), kScaleStartVarQ40);
  if (use_tof) {
    const int64_t q_res = ((residual_ < 0 ? 0 : int64_t{residual_}) * kInvMaxResidualQ16) >> 16;  // Q16
    // q_change = |A| tau / (kFusionScaleMaxChange |z|), one division
    const int64_t change_limit = (kScaleMaxChangeQ16 * abs64(tof.v)) >> 16;  // Q16 m/s
    const int64_t q_change =
        change_limit > 0 ? fx::div_q(abs64(accel_) * tau_us, change_limit * 1000000, 16) : fx::kInt32Max;
    // The window [t - tau, t] and the frame interval holding its start measured throughout.
    const bool whole_window = measured_us_ >= tau_us + dt_us;
    // q_short = kFusionScaleShortFrames dt / tau (tau_us > 0: tau >= 1 us)
    const int64_t q_short = fx::div_q(kShortFramesQ16 * dt_us, tau_us > 0 ? tau_us : 1, 0);
    const int64_t q_turn = in.scale_max_turn > 0 ? fx::div_q(tof.turn, in.scale_max_turn, 16) : 0;
    if (whole_window && q_res < kSoftCutQ16 && q_change < kSoftCutQ16 && q_short < kSoftCutQ16 && q_turn < kSoftCutQ16)
      learn_scale(in, dt_us, q_res, q_change, q_short, q_turn);
  }

  // The output's smoothing time constant: slower where the differential is
  // doubtful (residual), unless a time of flight joins it this frame (below).
  // The differential's lag is added back as that of the output it makes alone,
  // whether or not a time of flight joins it: one that comes and goes would
  // otherwise switch the differential's own value frame by frame.
  const int64_t slowed_tau_us = kTauUs + ((kSlowUsPerResidual * residual_) >> 16);
  const int64_t vd = fx::shr_round(int64_t{in.v_differential} * inv_scale_, fx::kScaleFrac) +
                     lag_compensation(in, dt_us, slowed_tau_us);  // Q16
  // Before the observer has measured anything since the (re)start (a scene
  // too far or too plain for the stereo difference: a facade 30 m away),
  // a track that has held kTofWindowGateFrames, and does not run against the
  // images, makes V alone; once the observer has measured, a frame it cannot
  // measure holds V as before (over a held value's time, a track on weak
  // texture scatters more than the held value errs: the photo walls' plain
  // ends doubled their E).
  const bool tof_alone = !in.direct && !direct_seen_ && use_tof && tof.frames >= kTofWindowGateFrames &&
                         in.image_direction != 0 && (tof.v > 0) == (in.image_direction > 0);
  if (in.direct) direct_seen_ = true;
  if (!in.direct && !tof_alone) {  // nothing measured: V held ...
    // ... unless it runs against the images' direction of travel: a value
    // that a repeating texture made (a picket fence: -7 m/s at +0.5, held
    // through seconds of low texture) is let go to 0 at the output's pace.
    if (in.against_images) v_ = fx::sat32(v_ - fx::div_q(int64_t{v_} * dt_us, kTauUs + dt_us, 0, &sat), &sat);
    out.v = v_;
    out.saturated = sat;
    return out;
  }
  if (!started_ && !tof_alone) {
    v_ = fx::sat32(vd, &sat);
    started_ = true;
    out.v = v_;
    out.saturated = sat;
    return out;
  }
  // Uncertainties (m/s, Q16).
  const int64_t root_res = fx::isqrt32(static_cast<uint32_t>(residual_ < 0 ? 0 : residual_) << 16);  // Q16
  const int64_t speed = abs64(vd) > abs64(v_) ? abs64(vd) : abs64(v_);
  // The differential's variance (Q32): its own, and that of the scale it is
  // divided by (var Q40 x speed^2 Q16 >> 24, the speed held to
  // kFusionScaleTermMaxSpeed: speed^2 < 2^28, var < 2^31).
  const int64_t sd = (((kDiffFloorQ16 + ((kDiffPerResidualQ16 * root_res) >> 16)) * speed) >> 16) + kSpeedFloorQ16;
  const int64_t held = speed < kScaleTermMaxSpeedQ16 ? speed : kScaleTermMaxSpeedQ16;
  const int64_t sd2 = sd * sd + fx::shr_round(((held * held) >> 16) * scale_var_, 24);
  int64_t target = vd;
  if (use_tof) {
    // z + A tau / 2: A tau_us < 2^40, times 2^40 / 2e6 (< 2^20) < 2^60
    const int64_t moved = shown_move(in, fx::shr_round(move_rate() * tau_us * kHalfPerMillionQ40, 40), tau_us);
    const int64_t zc = int64_t{tof.v} + moved;
    const int64_t inflated = (int64_t{tof.sig} * fx::isqrt32(static_cast<uint32_t>(tof_inflation_))) >> 8;  // sig sqrt(n), Q16
    const int64_t rel = inflated > kTofFloorQ16 ? inflated : kTofFloorQ16;
    const int64_t st = ((rel * abs64(tof.v)) >> 16) + kSpeedFloorQ16;
    // The move to the present is as uncertain as kFusionTofMoveShare of itself
    // (|moved| <= kFusionAccelMax kTofMaxTau / 2 = 3 m/s < 2^18 in Q16: its square < 2^36).
    const int64_t move_sd = (kMoveShareQ16 * abs64(moved)) >> 16;
    const int64_t st2 = st * st + move_sd * move_sd;  // Q32
    // Against its direction as moved to the present (zc: a window that spans a
    // reversal keeps the direction of its mean, not of the present), and only
    // where that direction is clear (|zc| beyond kFusionAgainstSigmas of its sigma;
    // |zc| < 2^31 + 2^18: its square fits int64, as does 4 st2 < 2^44 in Q8).
    const bool against = !tof_alone && (vd > 0) != (zc > 0) && abs64(vd) > ((kAgainstSigmasQ16 * sd) >> 16) &&
                         zc * zc > ((kAgainstSigmas2Q8 * st2) >> 8);
    failed_ = against;
    failed_us_ = 0;
    const int64_t w = against || tof_alone ? kOneQ16 : fx::fraction_q16(sd2, sd2 + st2);
    target = vd + ((w * (zc - vd)) >> 16);
    coast_z_ = zc;
    coast_st2_ = st2;
    coast_us_ = 0;
    coast_frames_ = 0;
    // How far the time of flight really scatters, seen against a clean differential.
    if (residual_ < kScaleMaxResidualQ16 && !against && !tof_alone) {
      const int64_t nu = int64_t{tof.v} - vd;
      const int64_t g = fx::div_q(nu * nu, st2 + sd2, 16);  // Q16
      tof_inflation_ = static_cast<int32_t>(
          fx::clamp64(tof_inflation_ + fx::shr_round(kInflationGainQ16 * (g - tof_inflation_), 16), kOneQ16, kInflationMaxQ16));
    }
  }
  if (!use_tof) {
    // A track held through a miss: its last value, moved on by the fused rate,
    // its sigma grown by kFusionCoastSigmaGrowth per frame (fusion_params.hpp).
    // (st2 < 2^42, times (2 x 6)^2 at most: kTofTrackMisses frames.)
    if (tof.held && coast_frames_ >= 0 && !failed_) {
      coast_us_ = std::min<int64_t>(coast_us_ + dt_us, kInt31);
      ++coast_frames_;
      const int64_t zc = coast_z_ + fx::div_trunc(move_rate() * coast_us_, 1000000);
      const int64_t grow = kCoastGrowth * (coast_frames_ + 1);
      const int64_t st2 = coast_st2_ * grow * grow;
      const int64_t w = fx::fraction_q16(sd2, sd2 + st2);
      target = vd + ((w * (zc - vd)) >> 16);
    } else {
      coast_frames_ = -1;
    }
  }
  if (!use_tof && failed_) {
    // Failed against the last time of flight: held until it agrees again (fusion_params.hpp).
    failed_us_ = std::min<int64_t>(failed_us_ + dt_us, kInt31);
    const bool agrees = (vd > 0) == (v_ > 0) || abs64(vd) <= ((kAgainstSigmasQ16 * sd) >> 16);
    if (agrees || failed_us_ > kFailedHoldUs) {
      failed_ = false;
    } else {
      out.v = v_;
      out.saturated = sat;
      return out;
    }
  }
  // Smoothing, slower without a time of flight when the differential is doubtful,
  // but never longer than the output has measured since it (re)started: until
  // then it is the mean of what came since (gain 1/n), not the first value held.
  if (!started_) {  // (a start on the time of flight alone)
    v_ = fx::sat32(target, &sat);
    started_ = true;
    out.v = v_;
    out.used_tof = true;
    out.saturated = sat;
    return out;
  }
  since_start_us_ = std::min<int64_t>(since_start_us_ + dt_us, kInt31);
  const int64_t teff_us = std::min<int64_t>(use_tof ? kTauUs : slowed_tau_us, since_start_us_);
  const int64_t nv = v_ + fx::div_q((target - v_) * dt_us, teff_us + dt_us, 0, &sat);
  if (dt_us > 0) {
    // accel += (rate - accel) dt / (tau_a + dt), with rate = (nv - v) / dt: one division.
    accel_ = static_cast<AccelQ16>(fx::clamp64(
        accel_ + fx::div_q((nv - v_) * 1000000 - int64_t{accel_} * dt_us, kAccelTauUs + dt_us, 0, &sat),
        -kAccelMaxQ16, kAccelMaxQ16));
    move_accel_ = static_cast<AccelQ16>(fx::clamp64(
        move_accel_ + fx::div_q((nv - v_) * 1000000 - int64_t{move_accel_} * dt_us, kMoveAccelTauUs + dt_us, 0, &sat),
        -kAccelMaxQ16, kAccelMaxQ16));
  }
  v_ = fx::sat32(nv, &sat);
  out.v = v_;
  out.used_tof = use_tof;
  out.saturated = sat;
  return out;
}

int64_t VelocityFusion::clean_share() const {
  // 1 up to the clean residual, 0 from kFusionMoveAccelResidual, linear between (and 0
  // while the differential stands failed against the time of flight: its residual misses that).
  if (failed_ || residual_ >= kMoveAccelResidualQ16) return 0;
  if (residual_ > kScaleMaxResidualQ16) return ((kMoveAccelResidualQ16 - residual_) * kMoveBlendSlopeQ16) >> 16;  // < 2^13 x 2^20
  return kOneQ16;
}

int64_t VelocityFusion::move_rate() const {
  // The faster rate in the measure that the differential is clean.
  return accel_ + ((clean_share() * (int64_t{move_accel_} - accel_)) >> 16);
}

int64_t VelocityFusion::shown_move(const FusionInput& in, int64_t moved, int64_t tau_us) const {
  // In the measure that the differential is clean (clean_share, as the
  // move's rate), the move is held to what the observer shows, as the lag
  // term is: its lag 2 (V_half - V) = tau_obs A on a ramp, so tau / 2 of that
  // rate is (V_half - V) tau / tau_obs. A outlasts a change of acceleration
  // by its smoothing (a start: the window, all after it, moved on by a rate
  // that had passed); the shown lag does not. Among clutter the shown lag is
  // noise and the move stands. (Continuous in the residual and in both
  // values, so that the twin's last bits cannot switch it.)
  const int64_t share = clean_share();
  if (share == 0 || in.observer_tau_us == 0) return moved;
  // |V_half - V| held to kLagMaxQ16 (2^23), tau_us < 2^20: < 2^43
  const int64_t half_lag = fx::clamp64(int64_t{half_} - in.v_differential, -kLagMaxQ16, kLagMaxQ16);
  const int64_t cap = fx::div_trunc(half_lag * tau_us, in.observer_tau_us);
  const int64_t held = (cap > 0) != (moved > 0) ? 0 : (abs64(cap) < abs64(moved) ? cap : moved);
  return moved + ((share * (held - moved)) >> 16);  // |moved| < 2^18 (kFusionAccelMax kTofMaxTau / 2)
}

int64_t VelocityFusion::lag_compensation(const FusionInput& in, int64_t dt_us, int64_t out_tau_us) {
  if (!in.direct || dt_us <= 0) return 0;
  if (!have_direct_) {  // (re)start: from the observer's V, no lag known
    half_ = in.v_differential;
    prev_direct_ = in.v_direct;
    have_direct_ = true;
    return 0;
  }
  const int64_t tau_us = in.observer_tau_us;
  // The scatter of the direct values: half the mean square of their differences.
  const int64_t dv = fx::clamp64(int64_t{in.v_direct} - prev_direct_, -kLagMaxQ16, kLagMaxQ16);
  direct_var_ += ((dv * dv - direct_var_) * fx::fraction_q16(dt_us, kAccelTauUs + dt_us)) >> 16;  // Q32 <= 2^46
  prev_direct_ = in.v_direct;
  // The lag from the fused rate, c = tau A, weighed by how far it stands out
  // of its noise: A is the innovation smoothed over tau_a, so var_c =
  // sigma^2 dt / (2 tau_a + dt), sigma^2 = var / 2; and of the differential's
  // own floor (kFusionDiffFloor of the speed: a lag below it is not one the
  // differential can tell from its texture's slow errors).
  const int64_t c = fx::clamp64(fx::div_trunc(int64_t{accel_} * tau_us, 1000000), -kLagMaxQ16, kLagMaxQ16);  // Q16
  const int64_t floor_sd = (kDiffFloorQ16 * std::min(abs64(in.v_differential), kLagMaxQ16)) >> 16;  // Q16
  const int64_t var_c =
      (((direct_var_ >> 1) * fx::fraction_q16(dt_us, 2 * kAccelTauUs + dt_us)) >> 16) + floor_sd * floor_sd;  // Q32
  const int64_t c2 = c * c;  // Q32, <= 2^46
  const int64_t den = c2 + ((kLagSigmas2Q8 * var_c) >> 8);
  const int64_t weighed = den > 0 ? fx::shr_round(fx::fraction_q16(c2, den) * c, 16) : 0;
  // ... and never beyond the lag the observer shows now, 2 (V_half - V) with
  // V_half the same observer at half its time constant: A outlasts a step by
  // tau_a, the observer's lag does not.
  bool sat = false;  // (the term is held to kLagMaxQ16 below)
  half_ = observer_step(half_, in.v_direct, dt_us, tau_us / 2, &sat);
  const int64_t shown = fx::clamp64(2 * (int64_t{half_} - in.v_differential), -kLagMaxQ16, kLagMaxQ16);
  if ((weighed > 0) != (shown > 0) || weighed == 0 || shown == 0) return 0;
  const int64_t lag = abs64(weighed) < abs64(shown) ? weighed : shown;
  // The same ramp lags twice more downstream: the direct values stand for the
  // middle of their interval (dt / 2), and the output's own smoothing (out_tau_us).
  // |lag| <= 2^23 times < 2^32 us: < 2^55
  return fx::div_q(lag * (tau_us + dt_us / 2 + out_tau_us), tau_us, 0);
}

void VelocityFusion::learn_scale(const FusionInput& in, int64_t dt_us, int64_t q_res, int64_t q_change,
                                 int64_t q_short, int64_t q_turn) {
  const TofResult& tof = *in.tof;
  const int64_t disp = int64_t{tof.direction} * in.baseline;  // Q24 m
  // travel (Q16 m/s x ns) over h (Q24 m) in Q24: travel 2^8 / (h 1e9); travel < 2^50 over the window
  const int64_t ratio = fx::div_q(fx::travel_between(in.y, tof.y_then) * 256, disp * 1000000000, fx::kScaleFrac);
  if (ratio <= 0) return;
  const int64_t measured = fx::clamp64(ratio, kScaleMinQ24, kScaleMaxQ24);
  if (!scale_started_) {
    scale_ = int32_t{1} << fx::kScaleFrac;
    scale_var_ = kScaleStartVarQ40;
    scale_started_ = true;
  }
  const int64_t sig = fx::clamp64(tof.sig, kTofFloorQ16, kOneQ16);
  // frames in the window, in ns as the twin (32-bit: tau < 0.6 s, dt < 2^31 ns)
  const uint32_t dt32 = static_cast<uint32_t>(std::min<int64_t>(in.dt_ns, kInt31 - 1));
  const int64_t frames =
      dt_us > 0 ? static_cast<int64_t>((static_cast<uint32_t>(tof.tau_ns) + dt32 - 1) / dt32) : 1;
  const int64_t r = ((sig * sig * 4) << 8) * (frames > 1 ? frames : 1);  // Q32 -> Q40, < 2^48
  // 1 + q_res^4 + q_change^4 + q_short^4 + q_turn^4 in Q16, < 325 with q < 3
  const int64_t qr2 = (q_res * q_res) >> 16, qc2 = (q_change * q_change) >> 16, qs2 = (q_short * q_short) >> 16,
                qt2 = (q_turn * q_turn) >> 16;
  const int64_t penalty = kOneQ16 + ((qr2 * qr2) >> 16) + ((qc2 * qc2) >> 16) + ((qs2 * qs2) >> 16) + ((qt2 * qt2) >> 16);
  const int64_t r_weighed = (r >> 16) * penalty;  // < 2^32 x 325 x 2^16 < 2^57
  // The gain in Q24 and rounded steps: the gain falls to 1e-4 and below
  // once the scale is known, where Q16 and truncation drift the scale by
  // 1e-3 an hour against the twin. var <= kFusionScaleStartVar (2^30 in
  // Q40) times 2^24 stays below 2^55.
  const int64_t k = fx::div_q(scale_var_, scale_var_ + r_weighed, kGainFrac);
  scale_ = static_cast<ScaleQ24>(
      fx::clamp64(scale_ + fx::shr_round(k * (measured - scale_), kGainFrac), kScaleMinQ24, kScaleMaxQ24));
  scale_var_ -= fx::shr_round(scale_var_ * k, kGainFrac);
  // 1 / scale in Q24 (scale in [0.5, 2]): the differential is divided by it every frame.
  inv_scale_ = fx::div_q(int64_t{1} << (2 * fx::kScaleFrac), scale_, 0);  // 2^48 / scale_Q24 = 1/scale in Q24
}

}  // namespace lumavel
