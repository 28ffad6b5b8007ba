// Twin of firmware/core/src/image_direction.cpp.
#include "lumavel/host/float_image_direction.hpp"

#include <algorithm>
#include <cmath>

#include "lumavel/core/fusion_params.hpp"

namespace lumavel::host {

void FloatImageDirection::update(const FloatStereoMeasurement& prev, const FloatStereoMeasurement& cur, double dtheta,
                                 double dt_ns, int look) {
  if (look == 0 || dt_ns <= 0) {
    direction_ = 0;
    return;
  }
  double num = 0, den = 0;
  for (int i = 0; i < 2; ++i) {
    const Eigen::VectorXd rb = (cur.r[i] + prev.r[i]) / 2;
    num += (cur.f[i] - prev.f[i] - dtheta * rb).cwiseMax(-8.0).cwiseMin(8.0).dot(rb);  // (the core's clamp)
    den += rb.squaredNorm();
  }
  if (den <= 0) return;
  const double rate = std::clamp(-look * std::clamp(num / den, -8.0, 8.0) * 1e9 / dt_ns, -64.0, 64.0);
  const double a = std::min(1.0, dt_ns / (params::kImageDirectionTau * 1e9));
  mean_ += a * (rate - mean_);
  var_ += a * ((rate - mean_) * (rate - mean_) - var_);
  const double k = params::kImageDirectionSigmas;
  const bool clear = std::fabs(mean_) > params::kImageDirectionMinRate && mean_ * mean_ > k * k * var_;
  direction_ = clear ? (mean_ > 0 ? 1 : -1) : 0;
}

bool FloatImageDirection::against(double v) const {
  // (in the core's Q16 steps, so that the two engines draw the line alike)
  const double limit = std::ldexp(std::llround(std::ldexp(params::kImageDirectionFlagSpeed, 16)), -16);
  return (direction_ > 0 && v < -limit) || (direction_ < 0 && v > limit);
}

int float_image_look(const CameraModel& cam0, const CameraModel& cam1) {
  const double s = (std::sin(cam0.axis_yaw) + std::sin(cam1.axis_yaw)) / 2;
  if (s >= params::kImageDirectionMinLook) return 1;
  if (s <= -params::kImageDirectionMinLook) return -1;
  return 0;
}

}  // namespace lumavel::host
