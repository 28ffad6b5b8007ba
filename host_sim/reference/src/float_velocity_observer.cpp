// Twin of firmware/core/src/velocity_observer.cpp.
#include "lumavel/host/float_velocity_observer.hpp"

#include <algorithm>
#include <cmath>

#include "lumavel/core/estimator_params.hpp"
#include "lumavel/units/fixed.hpp"

namespace lumavel::host {
namespace {

// x / tan(x) with x = k h / 2 clamped as the core clamps it (x_over_tan_q30):
// dM = (d/h) S x / tan(x).
double x_over_tan(double x) {
  x = std::clamp(x, -params::kMaxHalfPhase, params::kMaxHalfPhase);
  return std::fabs(x) > 1e-12 ? x / std::tan(x) : 1.0;
}

// The core holds the step's ratio d / h in ValueQ28 (32 bits): beyond -8 ..
// (2^31 - 1) / 2^28 baselines a frame its division saturates there and says
// so (SATURATED); the twin stops at the same values and says so too.
const double kRatioMin = -std::ldexp(1.0, 31 - fx::kValueFrac);
const double kRatioMax = std::ldexp(static_cast<double>(fx::kInt32Max), -fx::kValueFrac);
double saturating(double ratio, bool* sat) {
  if (ratio > kRatioMax || ratio < kRatioMin) *sat = true;
  return std::clamp(ratio, kRatioMin, kRatioMax);
}

// The finite step in time: the ratio d / h that explains e once each kernel's
// innovation is scaled by y / tan(y), y = x_k d / h (velocity_observer.cpp).
double step_corrected_ratio(const Eigen::VectorXd& e, const Eigen::VectorXd& a, const Eigen::VectorXd& half,
                            double ratio, double den, bool* sat) {
  double num = 0;
  for (Eigen::Index k = 0; k < e.size(); ++k) num += e[k] * x_over_tan(half[k] * ratio) * a[k];
  return saturating(num / den, sat);
}

// Its fixed point: two evaluations and Aitken's extrapolation where the
// iterates alternate (else the second iterate), as the core.
double solve_step_correction(const Eigen::VectorXd& e, const Eigen::VectorXd& a, const Eigen::VectorXd& half,
                             double r0, double den, bool* sat) {
  const double r1 = step_corrected_ratio(e, a, half, r0, den, sat);
  const double r2 = step_corrected_ratio(e, a, half, r1, den, sat);
  const double d1 = r1 - r0, d2 = r2 - r1;
  if ((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) return r2 - d2 * d2 / (d2 - d1);
  return r2;
}

}  // namespace

FloatVelocityObserver::FloatVelocityObserver(uint32_t tau_us)
    : converging_us_(static_cast<int64_t>(params::kConvergingTaus * static_cast<double>(tau_us))) {}

FloatObserverOutput FloatVelocityObserver::update(const FloatObserverInput& in) {
  FloatObserverOutput out;
  const FloatStereoMeasurement& cur = *in.cur;
  const FloatStereoMeasurement& prev = *in.prev;
  const Eigen::VectorXd s_bar = (cur.diff + prev.diff) / 2;
  const Eigen::VectorXd r_bar = (cur.rot + prev.rot) / 2;
  // Innovation with the rotation term removed.
  Eigen::VectorXd e = (cur.mid - prev.mid) - in.dtheta * r_bar;
  Eigen::VectorXd a = s_bar;
  const Eigen::VectorXd half = (cur.half_phase + prev.half_phase) / 2;
  if (in.baseline_correction)
    for (Eigen::Index k = 0; k < a.size(); ++k) a[k] *= x_over_tan(half[k]);
  // Observability of the interval: the weaker of its two frames.
  const double ss_min = std::min(cur.diff.squaredNorm(), prev.diff.squaredNorm());
  out.texture = s_bar.size() ? std::sqrt(ss_min / static_cast<double>(s_bar.size())) : 0;
  const double den = a.squaredNorm();
  if (den <= 0 || s_bar.squaredNorm() <= 0 || out.texture < in.low_texture) {
    out.v = v_;
    return out;
  }
  // Distance over the interval: d = h e.A / A.A.
  bool sat = false;
  double d = in.baseline * saturating(e.dot(a) / den, &sat);
  if (in.baseline_correction) {
    d = in.baseline * solve_step_correction(e, a, half, d / in.baseline, den, &sat);
    for (Eigen::Index k = 0; k < e.size(); ++k) e[k] *= x_over_tan(half[k] * d / in.baseline);  // (the residual as corrected)
  }
  out.v_direct = d / in.dt;
  const double ee = e.squaredNorm();
  out.residual = ee > 0 ? std::min((e - (d / in.baseline) * a).squaredNorm() / ee, 1.0) : 0.0;
  if (!started_) {
    v_ = out.v_direct;
    started_ = true;
    since_start_us_ = 0;
    tau_now_ = young_time_constant(since_start_us_, in.tau);
  } else {
    // Implicit Euler of dV/dt = (v_direct - V) / tau.
    since_start_us_ += static_cast<int64_t>(in.dt_ns / 1000);
    tau_now_ = young_time_constant(since_start_us_, in.tau);
    v_ = observer_step(v_, out.v_direct, in.dt, tau_now_);
  }
  out.v = v_;
  out.updated = true;
  out.saturated = sat;
  return out;
}

}  // namespace lumavel::host
