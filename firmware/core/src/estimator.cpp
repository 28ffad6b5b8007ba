#include "lumavel/core/estimator.hpp"

#include <algorithm>

#include "lumavel/core/column_profile.hpp"
#include "lumavel/core/estimator_params.hpp"
#include "lumavel/core/fusion_params.hpp"
#include "lumavel/core/imath.hpp"
#include "lumavel/core/photometric_params.hpp"
#include "lumavel/core/status.hpp"

namespace lumavel {
namespace {

// distance += v * dt: Q16 m/s * ns -> Q32 m, split to stay inside int64. The
// division's remainder is carried to the next frame (floor division), so that
// no truncation adds up (0.2 mm a day at 60 Hz, 3 mm at 1 kHz, before).
DistQ32 advance(DistQ32 s, SpeedQ16 v, int64_t dt_ns, int64_t* rem) {
  const int64_t x = int64_t{v} * dt_ns;  // Q16 m/s * ns, |x| < 2^31 * 2^32
  constexpr int64_t kNsPerS = 1000000000;
  const int64_t ip = x / kNsPerS;
  const int64_t frac = (x % kNsPerS) * 65536 + *rem;  // |.| < 2^47
  int64_t q = frac / kNsPerS, r = frac % kNsPerS;
  if (r < 0) {
    r += kNsPerS;
    --q;
  }
  *rem = r;
  return s + ip * 65536 + q;
}

// The frame gap's threshold in frame periods, Q4 (exact for 1.5).
constexpr int kFrameGapFrac = 4;
constexpr int64_t kFrameGapPeriodsQ4 = fx::q_of(params::kFrameGapPeriods, kFrameGapFrac);
static_assert(fx::q_of(params::kFrameGapPeriods, 30) == kFrameGapPeriodsQ4 << (30 - kFrameGapFrac),
              "the gap factor must be exact in Q4");

}  // namespace

ConfigError Estimator::configure(const EstimatorConfig& cfg) {
  const ConfigError e = validate(cfg);
  if (e != ConfigError::kOk) return e;
  cfg_ = cfg;
  build_kernel_bank(cfg_, bank_);
  AngleQ28 narrowest = cfg_.kernels[0].sigma;
  for (int k = 1; k < cfg_.kernel_count; ++k)
    if (cfg_.kernels[k].sigma < narrowest) narrowest = cfg_.kernels[k].sigma;
  constexpr int64_t kRotationQ16 = fx::q_of(params::kTofMaxRotationSigma, 16);
  tof_max_rotation_ = static_cast<AngleQ28>((kRotationQ16 * narrowest) >> 16);
  constexpr int64_t kMatchRotationQ16 = fx::q_of(params::kMatchMaxRotationSigma, 16);
  match_max_rotation_ = static_cast<AngleQ28>((kMatchRotationQ16 * narrowest) >> 16);
  constexpr int64_t kScaleTurnQ16 = fx::q_of(params::kFusionScaleMaxTurnSigma, 16);
  scale_max_turn_ = static_cast<AngleQ28>((kScaleTurnQ16 * narrowest) >> 16);
  // The lens tables are the caller's: the kernel tables are built from them now.
  cfg_.edge_offsets[0] = cfg_.edge_offsets[1] = nullptr;
  look_ = image_look(cfg_.cam[0], cfg_.cam[1]);
  configured_ = true;
  reset();
  return ConfigError::kOk;
}

void Estimator::reset() {
  gyro_.reset();
  gyro_offset_.reset();
  heading_ = 0;
  observer_.reset();
  tof_.reset();
  direction_.reset();
  fusion_.reset();
  balance_.reset();
#if LUMAVEL_MATCH_FRAMES > 0
  match_.reset();
  jac_held_ = false;
#endif
  y_ = 0;
  have_prev_ = false;
  cur_ = 0;
  prev_t_ns_ = 0;
  prev_gyro_angle_ = 0;
  frame_index_ = 0;
  have_prev_frame_ = false;
  distance_ = 0;
  distance_rem_ = 0;
}

Estimate Estimator::step(const FramePair& frames) {
  ColumnProfile p[2];
  RadialSums radial1;  // cam1's, for the photometric match's rows' share of the vignetting
  bool radial = false;
  if (configured_) {
    column_profile(frames.cam[0], cfg_.width, cfg_.height, frames.stride, bank_.column_band(), p[0]);
    radial = column_profile(frames.cam[1], cfg_.width, cfg_.height, frames.stride, bank_.column_band(), p[1],
                            cam1_rings(), &radial1);
  }
  return step_profiles(frames.t_ns, p[0], p[1], radial ? &radial1 : nullptr);
}

Estimate Estimator::step_profiles(uint64_t t_ns, ColumnProfile& p0, ColumnProfile& p1, const RadialSums* radial1) {
  Estimate est{};
  est.t_ns = t_ns;
  est.frame_index = frame_index_++;
  if (!configured_) return est;
  const int next = have_prev_ ? 1 - cur_ : cur_;
  StereoMeasurement& m = meas_[next];
  // (on the sums as the cameras gave them: the mapping changes cam1's)
  const bool no_stereo = same_textured_profile(p0, p1, bank_.column_band(), cfg_.height);
  const bool matching = (cfg_.options & kOptionPhotometricMatch) != 0;  // (validate(): only where built in)
#if LUMAVEL_MATCH_FRAMES > 0
  if (matching) match_.apply(p1, bank_.column_band(), cfg_.height, radial1);
#endif
  kdot::Normaliser norm1{};  // (cam1's N for the match's Jacobian)
  stereo_measurement(p0, p1, bank_, (cfg_.options & kOptionPhotometricBalance) ? &balance_ : nullptr, m,
                     matching ? &norm1 : nullptr);
#if LUMAVEL_MATCH_FRAMES > 0
  // cam1's Jacobian every other frame, the last one's held between (it
  // follows the scene, which moves little in a frame; issue 14's cost): anew
  // after a frame without light and after p changed.
  MatchJac& jac = jac_;
  if (matching) {
    if (!jac_held_ || m.no_light) {
      match_.jacobian(p1, bank_.column_band(), cfg_.height, radial1, bank_.cam[1], bank_.count, m.f[1], jac, &norm1);
      jac_held_ = !m.no_light;
    } else {
      jac_held_ = false;
    }
  }
  MatchInput match_in{};
  match_in.usable = false;
#endif

  uint16_t status = 0;
  const uint32_t sampled = p0.clip_sampled + p1.clip_sampled;
  if (m.saturated || uint64_t{m.clipped} * 1000 > uint64_t{cfg_.saturated_permille} * sampled)
    status |= kStatusSaturated;

  const int64_t angle = gyro_.angle_at(t_ns);
  const int64_t since_prev_ns = have_prev_frame_ ? static_cast<int64_t>(t_ns - prev_t_ns_) : 0;
  // Gyro angle of the interval with the learned offset removed.
  const int64_t dtheta = have_prev_frame_ ? angle - prev_gyro_angle_ - gyro_offset_.take_angle_over(since_prev_ns) : 0;
  heading_ = have_prev_frame_ ? heading_ + dtheta : angle;
  est.heading = fx::wrap_pi(heading_);
  // Every frame whose interval [previous frame, this frame] the samples do not cover.
  const uint64_t gyro_gap_ns = uint64_t{cfg_.gyro_gap_us} * 1000;
  const uint64_t interval_start = have_prev_frame_ ? prev_t_ns_ : t_ns;
  if (gyro_.take_max_spacing() > gyro_gap_ns || !gyro_.covers(interval_start, t_ns, gyro_gap_ns))
    status |= kStatusGyroGap;
  // A railed gyro sample: the interval's rotation is unknown, V is held over it.
  const bool gyro_saturated = gyro_.saturated_since(interval_start);
  if (gyro_saturated) status |= kStatusSaturated;

  if (m.no_light || no_stereo) {
    // Unusable frame: hold V, and pair the next good frame with nothing.
    status |= (m.no_light ? kStatusNoLight : kStatusNoStereo) | kStatusLowTexture | kStatusNoTof;
    have_prev_ = false;
    gyro_offset_.drop_reference();
    tof_.reset();
    direction_.reset();
    fusion_.restart();
  } else if (!have_prev_) {
    status |= kStatusNoTof;
    have_prev_ = true;
    cur_ = next;
  } else {
    const int64_t dt_ns = static_cast<int64_t>(t_ns - prev_t_ns_);
    if (t_ns <= prev_t_ns_ || dt_ns > int64_t{cfg_.max_gap_us} * 1000) {
      status |= kStatusFrameGap | kStatusRestarted | kStatusNoTof;
      observer_.restart();
      gyro_offset_.drop_reference();
      tof_.reset();
      direction_.reset();
      fusion_.restart();
    } else {
      if (dt_ns * (1 << kFrameGapFrac) > int64_t{cfg_.frame_period_us} * 1000 * kFrameGapPeriodsQ4)
        status |= kStatusFrameGap;
      ObserverInput in{};
      in.prev = &meas_[cur_];
      in.cur = &m;
      in.dt_ns = dt_ns;
      in.dtheta = fx::sat32(dtheta);
      in.baseline = cfg_.baseline;
      in.tau_us = cfg_.tau_us;
      in.low_texture = cfg_.low_texture;
      in.baseline_correction = (cfg_.options & kOptionBaselineCorrection) != 0;
      const ObserverOutput o = gyro_saturated ? observer_.hold() : observer_.update(in);
      if (cfg_.options & kOptionGyroOffsetLearning) {
        if (status & (kStatusFrameGap | kStatusGyroGap)) gyro_offset_.drop_reference();
        gyro_offset_.update({&m, t_ns, angle, o.updated, cfg_.baseline, cfg_.still_distance, cfg_.still_min_us});
        if (gyro_offset_.still()) status |= kStatusStill;
      }
      if (o.saturated) status |= kStatusSaturated;
      est.v_direct = o.v_direct;
      est.texture = o.texture;
      // The time of flight: this frame on the history, then its match (not over
      // an interval whose rotation is unknown).
      // (the direct value: the observer's filtered V lags an acceleration, which
      // would read as a scale error against the time of flight)
      // (dt held below 2^31 ns, so the product stays below 2^62; y wraps by design)
      y_ += static_cast<TravelQ16Ns>(int64_t{o.updated ? o.v_direct : o.v} * std::min<int64_t>(dt_ns, int64_t{1} << 31));
      TofResult tof{};
      if (!gyro_saturated) {
        direction_.update(meas_[cur_], m, fx::sat32(dtheta), dt_ns, look_);
        TofFrame& tf = tof_.push();
        tf.t_ns = t_ns;
        tf.heading = heading_;
        tf.y = y_;
        for (uint8_t k = 0; k < m.count; ++k)
          for (int i = 0; i < 2; ++i) {
            tf.f[i][k] = m.f[i][k];
            tf.r[i][k] = m.r[i][k];
          }
        tof = tof_.track({cfg_.baseline, tof_max_rotation_, fusion_.v(), o.updated && !fusion_.differential_failed() ? fusion_.rescaled(o.v_direct) : fusion_.v(), m.count,
                           direction_.direction()});
      }
      FusionInput fin{};
      fin.dt_ns = dt_ns;
      fin.v_differential = o.v;
      fin.observer_tau_us = observer_.time_constant_us();
      fin.direct = o.updated;
      fin.v_direct = o.v_direct;
      fin.residual = o.residual;
      fin.tof = &tof;
      fin.y = y_;
      fin.baseline = cfg_.baseline;
      fin.scale_max_turn = scale_max_turn_;
      fin.against_images = direction_.against(fusion_.v());
      fin.image_direction = direction_.direction();
      const FusionOutput fo = fusion_.update(fin);
      if (!fo.used_tof) status |= kStatusNoTof;
      // (V held: neither the differential nor a time of flight measured it)
      if (!o.updated && !gyro_saturated && !fo.used_tof) status |= kStatusLowTexture;
      if (direction_.against(fo.v)) status |= kStatusAgainstImages;
      if (fo.saturated) status |= kStatusSaturated;
      est.tof_ns = tof.ok ? tof.tau_ns : 0;
      distance_ = advance(distance_, fo.v, dt_ns, &distance_rem_);
#if LUMAVEL_MATCH_FRAMES > 0
      match_in = {t_ns, heading_, {m.f[0], m.f[1]}, {m.r[0], m.r[1]}, &jac, m.count, fo.v, cfg_.baseline,
                  match_max_rotation_,
                  o.updated && !gyro_saturated && !(status & (kStatusSaturated | kStatusGyroGap | kStatusFrameGap))};
#endif
      // The balance (not where the rotation or the interval is in doubt: the
      // stereo prediction needs both).
      if ((cfg_.options & kOptionPhotometricBalance) && o.updated && !gyro_saturated &&
          !(status & (kStatusSaturated | kStatusGyroGap | kStatusFrameGap)))
        balance_.learn({&meas_[cur_], &m, fx::sat32(dtheta), cfg_.baseline});
    }
    cur_ = next;
  }
  // The photometric match learns from every clean interval (an unusable one
  // clears its history); new parameters move this frame's F1 as if it had
  // been taken with them, so that the next interval sees no step.
#if LUMAVEL_MATCH_FRAMES > 0
  if (matching && match_.learn(match_in)) {
    jac_held_ = false;
    for (uint8_t k = 0; k < m.count; ++k) {
      int64_t jp = 0;
      for (int j = 0; j < kMatchParams; ++j) jp += int64_t{jac[k][j]} * match_.delta(j);
      const int64_t df = fx::shr_round(jp, 30);
      m.f[1][k] = fx::sat32(m.f[1][k] + df);
      m.mid[k] = fx::sat32(m.mid[k] + fx::shr_round(df, 1));
      m.diff[k] = fx::sat32(m.diff[k] + df);
    }
  }
#else
  (void)matching;
  (void)radial1;  // (the rows' share is the match's)
#endif
  if (observer_.converging_now()) status |= kStatusConverging;
  prev_t_ns_ = t_ns;
  prev_gyro_angle_ = angle;
  have_prev_frame_ = true;
  est.v_differential = observer_.v();
  est.v = fusion_.v();
  est.scale = fusion_.scale();
  est.outvoted = fusion_.differential_failed();
  est.distance = distance_;
  est.status = status;
  est.gyro_offset = gyro_offset_.offset();
  return est;
}

}  // namespace lumavel
