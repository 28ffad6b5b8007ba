#include "lumavel/host/float_estimator.hpp"

#include <algorithm>
#include <cmath>

#include "lumavel/core/estimator_params.hpp"
#include "lumavel/core/fusion_params.hpp"
#include "lumavel/core/status.hpp"
#include "lumavel/host/float_column_profile.hpp"

namespace lumavel::host {

FloatEstimator::FloatEstimator(const EstimatorSettings& s) : s_(s) {
  // Same validation as the fixed engine (throws), and its timing thresholds
  // in integer nanoseconds, so that both flag on the same frames even at a tie.
  const EstimatorConfig c = to_fixed_config(s);
  gyro_gap_ns_ = uint64_t{c.gyro_gap_us} * 1000;
  frame_period_ns_ = uint64_t{c.frame_period_us} * 1000;
  max_gap_ns_ = uint64_t{c.max_gap_us} * 1000;
  converging_ns_ = static_cast<uint64_t>(params::kConvergingTaus * static_cast<double>(uint64_t{c.tau_us} * 1000));
  still_min_ns_ = uint64_t{c.still_min_us} * 1000;
  double narrowest = s.kernels.empty() ? 0 : s.kernels[0].sigma;
  for (const KernelModel& k : s.kernels) narrowest = std::min(narrowest, k.sigma);
  tof_max_rotation_ = params::kTofMaxRotationSigma * narrowest;
  bank_ = build_float_kernel_bank(s_);
  balance_ = FloatPhotometricBalance(static_cast<int>(s_.kernels.size()));
}

void FloatEstimator::push_gyro(uint64_t t_ns, double rate) {
  // What the fixed engine cannot represent is clipped to its range, as there.
  const RateQ24 q = to_fixed_rate(rate);  // throws if not finite
  const bool rail = fx::rate_at_rail(q);
  if (rail) rate = std::ldexp(static_cast<double>(q), -fx::kRateFrac);
  Gyro& g = gyro_;
  if (g.count == 0) {
    g.t[1] = t_ns;
    g.r[1] = rate;
    g.at_rail[1] = rail;
    g.angle[1] = 0;
    g.t_first = t_ns;
    g.count = 1;
    return;
  }
  if (t_ns <= g.t[1]) return;
  const double dt = static_cast<double>(t_ns - g.t[1]) * 1e-9;
  g.max_spacing = std::max(g.max_spacing, t_ns - g.t[1]);
  g.t[0] = g.t[1];
  g.r[0] = g.r[1];
  g.angle[0] = g.angle[1];
  g.at_rail[0] = g.at_rail[1];
  g.t[1] = t_ns;
  g.r[1] = rate;
  g.at_rail[1] = rail;
  g.angle[1] = g.angle[0] + (g.r[0] + g.r[1]) / 2 * std::min(dt, params::kGyroMaxStep);  // one piece at most, as the core
  if (g.at_rail[0] || g.at_rail[1]) {
    g.railed = true;
    g.railed_end = t_ns;
  }
  ++g.count;
}

double FloatEstimator::angle_at(uint64_t t) const {
  const Gyro& g = gyro_;
  if (g.count == 0) return 0;
  auto secs = [](uint64_t a, uint64_t b) { return (static_cast<double>(a) - static_cast<double>(b)) * 1e-9; };
  constexpr double kMax = params::kGyroMaxStep;  // held rates extrapolate this far at most
  if (t >= g.t[1]) return g.angle[1] + g.r[1] * std::min(secs(t, g.t[1]), kMax);
  if (g.count < 2) return g.angle[1] - g.r[1] * std::min(secs(g.t[1], t), kMax);
  if (t <= g.t[0]) return g.angle[0] - g.r[0] * std::min(secs(g.t[0], t), kMax);
  const double span = secs(g.t[1], g.t[0]), dt = secs(t, g.t[0]);
  const double rate_t = g.r[0] + (g.r[1] - g.r[0]) * dt / span;
  return g.angle[0] + (g.r[0] + rate_t) / 2 * dt;
}

bool FloatEstimator::gyro_covers(uint64_t from, uint64_t to) const {
  const Gyro& g = gyro_;
  if (g.count == 0) return false;
  if (from > to) std::swap(from, to);
  const uint64_t gap = gyro_gap_ns_;
  if (g.t_first > from + gap || to > g.t[1] + gap) return false;
  const uint64_t oldest = g.count < 2 ? g.t[1] : g.t[0];
  if (to + gap < oldest) return false;
  const bool hole = g.count >= 2 && g.t[1] - g.t[0] > gap;
  return !(hole && g.t[0] < to && g.t[1] > from);
}

bool FloatEstimator::gyro_saturated_since(uint64_t from) const {
  const Gyro& g = gyro_;
  return g.count > 0 && (g.at_rail[1] || (g.railed && g.railed_end > from));
}

EngineEstimate FloatEstimator::step(uint64_t t_ns, const uint8_t* cam0, const uint8_t* cam1) {
  EngineEstimate est;
  est.t_ns = t_ns;
  FloatColumnProfile p[2];
  const uint8_t* cam[2] = {cam0, cam1};
  for (int i = 0; i < 2; ++i) p[i] = float_column_profile(bank_.band, cam[i], s_.width, s_.height);
  const FloatStereoMeasurement m =
      float_stereo_measurement(p[0], p[1], bank_, s_.photometric_balance ? &balance_ : nullptr);
  uint16_t status = 0;
  const double sampled = p[0].clip_sampled + p[1].clip_sampled;
  if (m.clipped * 1000 > s_.saturated_permille * sampled) status |= kStatusSaturated;
  const double angle = angle_at(t_ns);
  const bool first = !have_prev_frame_;
  have_prev_frame_ = true;
  const double since_prev = first ? 0 : (static_cast<double>(t_ns) - static_cast<double>(prev_t_ns_)) * 1e-9;
  const double dtheta = first ? 0 : angle - prev_gyro_angle_ - offset_ * since_prev;
  heading_ = first ? angle : heading_ + dtheta;
  est.heading = std::remainder(heading_, 2 * M_PI);
  if (est.heading >= M_PI) est.heading -= 2 * M_PI;
  if (gyro_.max_spacing > gyro_gap_ns_ || !gyro_covers(first ? t_ns : prev_t_ns_, t_ns)) status |= kStatusGyroGap;
  gyro_.max_spacing = 0;
  const bool gyro_saturated = gyro_saturated_since(first ? t_ns : prev_t_ns_);  // V held over the interval
  if (gyro_saturated) status |= kStatusSaturated;
  auto converging = [&] { return !started_ || since_start_ns_ < converging_ns_; };
  const bool no_stereo = float_same_textured_profile(p[0], p[1], bank_.band);
  if (m.no_light || no_stereo) {
    status |= (m.no_light ? kStatusNoLight : kStatusNoStereo) | kStatusLowTexture | kStatusNoTof;
    have_prev_ = false;
    have_ref_ = still_ = false;  // GyroOffset::drop_reference
    tof_.reset();
    fusion_.restart();
  } else if (!have_prev_) {
    status |= kStatusNoTof;
    have_prev_ = true;
    prev_ = m;
  } else {
    const double dt = (static_cast<double>(t_ns) - static_cast<double>(prev_t_ns_)) * 1e-9;
    if (t_ns <= prev_t_ns_ || t_ns - prev_t_ns_ > max_gap_ns_) {
      status |= kStatusFrameGap | kStatusRestarted | kStatusNoTof;
      started_ = false;  // V held; the next interval re-initialises it
      since_start_ns_ = 0;
      have_ref_ = still_ = false;
      tof_.reset();
      fusion_.restart();
    } else {
      // (both sides exact in double: the same test as the core's integers)
      if (static_cast<double>(t_ns - prev_t_ns_) > params::kFrameGapPeriods * static_cast<double>(frame_period_ns_))
        status |= kStatusFrameGap;
      const Eigen::VectorXd s_bar = (m.diff + prev_.diff) / 2;
      const Eigen::VectorXd r_bar = (m.rot + prev_.rot) / 2;
      const Eigen::VectorXd e = (m.mid - prev_.mid) - dtheta * r_bar;
      Eigen::VectorXd a = s_bar;
      if (s_.baseline_correction) {
        // dM = (d/h) S x / tan(x), x = k h / 2 (velocity_observer.hpp).
        for (Eigen::Index j = 0; j < a.size(); ++j) {
          const double x = std::clamp((m.half_phase[j] + prev_.half_phase[j]) / 2, -params::kMaxHalfPhase,
                                      params::kMaxHalfPhase);
          a[j] *= std::fabs(x) > 1e-12 ? x / std::tan(x) : 1.0;
        }
      }
      const double ss_min = std::min(m.diff.squaredNorm(), prev_.diff.squaredNorm());
      est.texture = s_bar.size() ? std::sqrt(ss_min / static_cast<double>(s_bar.size())) : 0;
      const double den = a.squaredNorm();
      bool textured = false;
      double residual = 0;
      if (gyro_saturated) {
        est.texture = 0;
      } else if (den <= 0 || s_bar.squaredNorm() <= 0 || est.texture < s_.low_texture) {
        status |= kStatusLowTexture;
      } else {
        textured = true;
        const double d = s_.baseline * e.dot(a) / den;
        est.v_direct = d / dt;
        // VelocityObserver's residual ratio: the kernels' disagreement.
        const double ee = e.squaredNorm();
        residual = ee > 0 ? std::min((e - (d / s_.baseline) * a).squaredNorm() / ee, 1.0) : 0.0;
        if (!started_) {
          v_ = est.v_direct;
          started_ = true;
          since_start_ns_ = 0;
        } else {
          v_ += (est.v_direct - v_) * dt / (s_.tau + dt);
          since_start_ns_ += t_ns - prev_t_ns_;
        }
      }
      // The time of flight and the fusion (Estimator::step).
      y_ += (textured ? est.v_direct : v_) * dt;
      FloatTofResult tof;
      if (!gyro_saturated) {
        FloatTofFrame tf;
        tf.t_ns = t_ns;
        tf.heading = heading_;
        tf.y = y_;
        for (int i = 0; i < 2; ++i) {
          tf.f[i] = m.f[i];
          tf.r[i] = m.r[i];
        }
        tof_.push(tf);
        tof = tof_.track(s_.baseline, tof_max_rotation_, fusion_.v());
      }
      FloatFusionInput fin;
      fin.dt = dt;
      fin.v_differential = v_;
      fin.direct = textured;
      fin.v_direct = est.v_direct;
      fin.residual = residual;
      fin.tof = &tof;
      fin.y = y_;
      fin.baseline = s_.baseline;
      const FloatFusionOutput fo = fusion_.update(fin);
      if (!fo.used_tof) status |= kStatusNoTof;
      est.tof_s = tof.ok ? tof.tau_ns * 1e-9 : 0;
      if (s_.photometric_balance && textured && !gyro_saturated &&
          !(status & (kStatusSaturated | kStatusGyroGap | kStatusFrameGap)))
        balance_.learn(prev_, m, dtheta, s_.baseline);
      distance_ += fo.v * dt;
      if (s_.gyro_offset_learning) {
        if (status & (kStatusFrameGap | kStatusGyroGap)) have_ref_ = still_ = false;
        learn_offset(m, t_ns, angle, textured);
        if (still_) status |= kStatusStill;
      }
    }
    prev_ = m;
  }
  if (converging()) status |= kStatusConverging;
  prev_t_ns_ = t_ns;
  prev_gyro_angle_ = angle;
  est.v_differential = v_;
  est.v = fusion_.v();
  est.scale = fusion_.scale();
  est.distance = distance_;
  est.status = status;
  est.gyro_offset = offset_;
  return est;
}

void FloatEstimator::learn_offset(const FloatStereoMeasurement& m, uint64_t t_ns, double angle, bool textured) {
  auto anchor = [&] {
    ref_ = m;
    t_ref_ = t_ns;
    angle_ref_ = angle;
    have_ref_ = true;
    still_ = false;
  };
  if (!textured) {
    have_ref_ = still_ = false;
    return;
  }
  if (!have_ref_ || t_ns <= t_ref_) return anchor();
  const double den = m.diff.squaredNorm();
  if (den <= 0) {
    have_ref_ = false;
    return;
  }
  const double d = s_.baseline * (m.mid - ref_.mid).dot(m.diff) / den;
  if (std::fabs(d) > s_.still_distance) return anchor();
  const uint64_t span_ns = t_ns - t_ref_;  // compared in integer ns, as the core
  still_ = span_ns >= still_min_ns_;
  if (still_) {
    offset_ = (angle - angle_ref_) / (static_cast<double>(span_ns) * 1e-9);
    // Renewed as the core: not still again until still_min has passed.
    constexpr uint64_t kRenewNs = static_cast<uint64_t>(fx::q_of(params::kGyroOffsetRenewal * 1e9, 0));
    if (span_ns > kRenewNs) anchor();
  }
}

}  // namespace lumavel::host
