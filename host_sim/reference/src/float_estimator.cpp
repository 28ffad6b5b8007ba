// Twin of firmware/core/src/estimator.cpp.
#include "lumavel/host/float_estimator.hpp"

#include <algorithm>
#include <cmath>

#include "lumavel/core/estimator_params.hpp"
#include "lumavel/core/fusion_params.hpp"
#include "lumavel/core/photometric_params.hpp"
#include "lumavel/core/status.hpp"
#include "lumavel/host/float_column_profile.hpp"

namespace lumavel::host {

FloatEstimator::FloatEstimator(const EstimatorSettings& s) : s_(s) {
  // Same validation as the fixed engine (throws), and its timing thresholds
  // in integer nanoseconds.
  const EstimatorConfig c = to_fixed_config(s);
  gyro_gap_ns_ = uint64_t{c.gyro_gap_us} * 1000;
  frame_period_ns_ = uint64_t{c.frame_period_us} * 1000;
  max_gap_ns_ = uint64_t{c.max_gap_us} * 1000;
  still_min_ns_ = uint64_t{c.still_min_us} * 1000;
  observer_ = FloatVelocityObserver(c.tau_us);
  double narrowest = s.kernels.empty() ? 0 : s.kernels[0].sigma;
  for (const KernelModel& k : s.kernels) narrowest = std::min(narrowest, k.sigma);
  tof_max_rotation_ = params::kTofMaxRotationSigma * narrowest;
  match_max_rotation_ = params::kMatchMaxRotationSigma * narrowest;
  scale_max_turn_ = params::kFusionScaleMaxTurnSigma * narrowest;
  look_ = float_image_look(s_.cam[0], s_.cam[1]);
  bank_ = build_float_kernel_bank(s_);
  balance_ = FloatPhotometricBalance(static_cast<int>(s_.kernels.size()));
}

EngineEstimate FloatEstimator::step(uint64_t t_ns, const uint8_t* cam0, const uint8_t* cam1) {
  EngineEstimate est;
  est.t_ns = t_ns;

  FloatColumnProfile p[2];
  const uint8_t* cam[2] = {cam0, cam1};
  for (int i = 0; i < 2; ++i)
    p[i] = float_column_profile(bank_.band, cam[i], s_.width, s_.height, i == 1 && s_.photometric_match);
  // (on the sums as the cameras gave them: the mapping changes cam1's)
  const bool no_stereo = float_same_textured_profile(p[0], p[1], bank_.band);
  const bool matching = s_.photometric_match;
  if (matching) p[1] = match_.apply(p[1], bank_.band.rows);
  FloatStereoMeasurement m =
      float_stereo_measurement(p[0], p[1], bank_, s_.photometric_balance ? &balance_ : nullptr);
  // cam1's Jacobian every other frame, held between (the core's rule).
  if (matching) {
    if (!jac_held_ || m.no_light) {
      jac_ = match_.jacobian(p[1], bank_.band.rows, bank_.cam[1], m.f[1]);
      jac_held_ = !m.no_light;
    } else {
      jac_held_ = false;
    }
  }
  const Eigen::MatrixXd& jac = jac_;
  FloatPhotometricMatch::Input match_in{};
  match_in.usable = false;

  uint16_t status = 0;
  const double sampled = p[0].clip_sampled + p[1].clip_sampled;
  if (m.clipped * 1000 > s_.saturated_permille * sampled) status |= kStatusSaturated;

  const double angle = gyro_.angle_at(t_ns);
  const double since_prev =
      have_prev_frame_ ? (static_cast<double>(t_ns) - static_cast<double>(prev_t_ns_)) * 1e-9 : 0;
  // Gyro angle of the interval with the learned offset removed.
  const double dtheta = have_prev_frame_ ? angle - prev_gyro_angle_ - gyro_offset_.angle_over(since_prev) : 0;
  heading_ = have_prev_frame_ ? heading_ + dtheta : angle;
  est.heading = std::remainder(heading_, 2 * M_PI);
  if (est.heading >= M_PI) est.heading -= 2 * M_PI;
  const uint64_t interval_start = have_prev_frame_ ? prev_t_ns_ : t_ns;
  if (gyro_.take_max_spacing() > gyro_gap_ns_ || !gyro_.covers(interval_start, t_ns, gyro_gap_ns_))
    status |= kStatusGyroGap;
  const bool gyro_saturated = gyro_.saturated_since(interval_start);  // V held over the interval
  if (gyro_saturated) status |= kStatusSaturated;

  if (m.no_light || no_stereo) {
    status |= (m.no_light ? kStatusNoLight : kStatusNoStereo) | kStatusLowTexture | kStatusNoTof;
    have_prev_ = false;
    gyro_offset_.drop_reference();
    tof_.reset();
    direction_.reset();
    fusion_.restart();
  } else if (!have_prev_) {
    status |= kStatusNoTof;
    have_prev_ = true;
    prev_ = m;
  } else {
    const double dt = (static_cast<double>(t_ns) - static_cast<double>(prev_t_ns_)) * 1e-9;
    if (t_ns <= prev_t_ns_ || t_ns - prev_t_ns_ > max_gap_ns_) {
      status |= kStatusFrameGap | kStatusRestarted | kStatusNoTof;
      observer_.restart();
      gyro_offset_.drop_reference();
      tof_.reset();
      direction_.reset();
      fusion_.restart();
    } else {
      // (both sides exact in double: the same test as the core's integers)
      if (static_cast<double>(t_ns - prev_t_ns_) > params::kFrameGapPeriods * static_cast<double>(frame_period_ns_))
        status |= kStatusFrameGap;
      FloatObserverInput in;
      in.prev = &prev_;
      in.cur = &m;
      in.dt = dt;
      in.dt_ns = t_ns - prev_t_ns_;
      in.dtheta = dtheta;
      in.baseline = s_.baseline;
      in.tau = s_.tau;
      in.low_texture = s_.low_texture;
      in.baseline_correction = s_.baseline_correction;
      const FloatObserverOutput o = gyro_saturated ? observer_.hold() : observer_.update(in);
      if (s_.gyro_offset_learning) {
        if (status & (kStatusFrameGap | kStatusGyroGap)) gyro_offset_.drop_reference();
        gyro_offset_.update({&m, t_ns, angle, o.updated, s_.baseline, s_.still_distance, still_min_ns_});
        if (gyro_offset_.still()) status |= kStatusStill;
      }
      if (o.saturated) status |= kStatusSaturated;
      est.v_direct = o.v_direct;
      est.texture = o.texture;
      // The time of flight: this frame on the history, then its match (not
      // over an interval whose rotation is unknown).
      y_ += (o.updated ? o.v_direct : o.v) * dt;
      FloatTofResult tof;
      if (!gyro_saturated) {
        direction_.update(prev_, m, dtheta, static_cast<double>(t_ns - prev_t_ns_), look_);
        FloatTofFrame tf;
        tf.t_ns = t_ns;
        tf.heading = heading_;
        tf.y = y_;
        for (int i = 0; i < 2; ++i) {
          tf.f[i] = m.f[i];
          tf.r[i] = m.r[i];
        }
        tof_.push(tf);
        tof = tof_.track(direction_.direction(), s_.baseline, tof_max_rotation_, fusion_.v(), o.updated && !fusion_.differential_failed() ? o.v_direct / fusion_.scale() : fusion_.v());
      }
      FloatFusionInput fin;
      fin.dt = dt;
      fin.v_differential = o.v;
      fin.observer_tau = observer_.time_constant();
      fin.direct = o.updated;
      fin.v_direct = o.v_direct;
      fin.residual = o.residual;
      fin.tof = &tof;
      fin.y = y_;
      fin.baseline = s_.baseline;
      fin.scale_max_turn = scale_max_turn_;
      fin.against_images = direction_.against(fusion_.v());
      fin.image_direction = direction_.direction();
      const FloatFusionOutput fo = fusion_.update(fin);
      if (!fo.used_tof) status |= kStatusNoTof;
      // (V held: neither the differential nor a time of flight measured it)
      if (!o.updated && !gyro_saturated && !fo.used_tof) status |= kStatusLowTexture;
      if (direction_.against(fo.v)) status |= kStatusAgainstImages;
      est.tof_s = tof.ok ? tof.tau_ns * 1e-9 : 0;
      distance_ += fo.v * dt;
      match_in = {t_ns, heading_, {&m.f[0], &m.f[1]}, {&m.r[0], &m.r[1]}, &jac, fo.v, s_.baseline,
                  match_max_rotation_,
                  o.updated && !gyro_saturated && !(status & (kStatusSaturated | kStatusGyroGap | kStatusFrameGap))};
      // The balance (not where the rotation or the interval is in doubt).
      if (s_.photometric_balance && o.updated && !gyro_saturated &&
          !(status & (kStatusSaturated | kStatusGyroGap | kStatusFrameGap)))
        balance_.learn(prev_, m, dtheta, s_.baseline);
    }
    prev_ = m;
  }
  // The photometric match (as the core: an unusable interval clears its
  // history; new parameters move this frame's F1 by J dp).
  if (matching && match_.learn(match_in)) {
    jac_held_ = false;
    const Eigen::VectorXd df = jac * match_.delta();
    prev_.f[1] += df;
    prev_.mid += 0.5 * df;
    prev_.diff += df;
  }
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
  for (int j = 0; j < FloatPhotometricMatch::kParams; ++j) est.photometric[j] = match_.params()[j];
  est.photometric[2] *= params::kMatchOffsetUnitDn;
  return est;
}

}  // namespace lumavel::host
