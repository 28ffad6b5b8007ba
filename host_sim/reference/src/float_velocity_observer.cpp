// Twin of firmware/core/src/velocity_observer.cpp.
#include "lumavel/host/float_velocity_observer.hpp"

#include <algorithm>
#include <cmath>

#include "lumavel/core/estimator_params.hpp"

namespace lumavel::host {
namespace {

// x / tan(x) with x = k h / 2 clamped as the core clamps it (x_over_tan_q30):
// dM = (d/h) S x / tan(x).
double x_over_tan(double x) {
  x = std::clamp(x, -params::kMaxHalfPhase, params::kMaxHalfPhase);
  return std::fabs(x) > 1e-12 ? x / std::tan(x) : 1.0;
}

}  // namespace

FloatVelocityObserver::FloatVelocityObserver(uint32_t tau_us)
    : converging_ns_(static_cast<uint64_t>(params::kConvergingTaus * static_cast<double>(uint64_t{tau_us} * 1000))) {}

FloatObserverOutput FloatVelocityObserver::update(const FloatObserverInput& in) {
  FloatObserverOutput out;
  const FloatStereoMeasurement& cur = *in.cur;
  const FloatStereoMeasurement& prev = *in.prev;
  const Eigen::VectorXd s_bar = (cur.diff + prev.diff) / 2;
  const Eigen::VectorXd r_bar = (cur.rot + prev.rot) / 2;
  // Innovation with the rotation term removed.
  const Eigen::VectorXd e = (cur.mid - prev.mid) - in.dtheta * r_bar;
  Eigen::VectorXd a = s_bar;
  if (in.baseline_correction)
    for (Eigen::Index k = 0; k < a.size(); ++k) a[k] *= x_over_tan((cur.half_phase[k] + prev.half_phase[k]) / 2);
  // Observability of the interval: the weaker of its two frames.
  const double ss_min = std::min(cur.diff.squaredNorm(), prev.diff.squaredNorm());
  out.texture = s_bar.size() ? std::sqrt(ss_min / static_cast<double>(s_bar.size())) : 0;
  const double den = a.squaredNorm();
  if (den <= 0 || s_bar.squaredNorm() <= 0 || out.texture < in.low_texture) {
    out.v = v_;
    return out;
  }
  // Distance over the interval: d = h e.A / A.A.
  const double d = in.baseline * e.dot(a) / den;
  out.v_direct = d / in.dt;
  const double ee = e.squaredNorm();
  out.residual = ee > 0 ? std::min((e - (d / in.baseline) * a).squaredNorm() / ee, 1.0) : 0.0;
  if (!started_) {
    v_ = out.v_direct;
    started_ = true;
    since_start_ns_ = 0;
  } else {
    // Implicit Euler of dV/dt = (v_direct - V) / tau.
    v_ += (out.v_direct - v_) * in.dt / (in.tau + in.dt);
    since_start_ns_ += in.dt_ns;
  }
  out.v = v_;
  out.updated = true;
  return out;
}

}  // namespace lumavel::host
