// Twin of build_band and column_cos_q30 in firmware/core/src/kernel_bank.cpp (the sums it weighs: float_column_profile.cpp).
#include "lumavel/host/float_column_band.hpp"

#include <algorithm>
#include <cmath>

namespace lumavel::host {
namespace {



FloatColumnBand unbanded(int width, int height) {
  FloatColumnBand b;
  b.row_weight = Eigen::MatrixXd::Ones(height, width);
  b.rows = Eigen::VectorXd::Constant(width, height);
  for (auto& c : b.cos) c = Eigen::VectorXd::Ones(width);
  return b;
}

}  // namespace

Eigen::VectorXd float_column_cos(const CameraModel& cam, const Eigen::VectorXd& edges) {
  if (!cam.elevation_scale.empty())
    return Eigen::Map<const Eigen::VectorXd>(cam.elevation_scale.data(), static_cast<Eigen::Index>(cam.elevation_scale.size()));
  const double axis = cam.axis_yaw;
  const Eigen::Index w = edges.size() - 1;
  Eigen::VectorXd c(w);
  for (Eigen::Index u = 0; u < w; ++u) {
    const double a = (edges[u] + edges[u + 1]) / 2 - axis;
    c[u] = std::fabs(a) >= M_PI / 2 ? 0 : std::max(0.0, std::cos(a));
  }
  return c;
}

FloatColumnBand build_float_column_band(const EstimatorSettings& s, const Eigen::VectorXd (&edges)[2]) {
  const int w = s.width, h = s.height;
  if (h < 2 || !s.elevation_band) return unbanded(w, h);
  FloatColumnBand b;
  for (int i = 0; i < 2; ++i) b.cos[i] = float_column_cos(s.cam[i], edges[i]);
  if (b.cos[0].minCoeff() <= 0 || b.cos[1].minCoeff() <= 0) return unbanded(w, h);
  const Eigen::VectorXd mean = (b.cos[0] + b.cos[1]) / 2;
  const double cos_min = mean.minCoeff();
  const double half_q8 = h * 128.0;
  b.banded = true;
  b.row_weight = Eigen::MatrixXd::Zero(h, w);
  for (int u = 0; u < w; ++u) {
    // The core's rounding: b_u in whole 1/256 rows, the two edge rows' weight with it.
    const double b_q8 = std::min(half_q8, std::round(half_q8 * cos_min / mean[u]));
    if (b_q8 < 256) return unbanded(w, h);
    const double excluded_q8 = half_q8 - b_q8;
    const int first = static_cast<int>(std::ceil(excluded_q8 / 256));
    for (int v = first; v < h - first; ++v) b.row_weight(v, u) = 1;
    if (first > 0) b.row_weight(first - 1, u) = b.row_weight(h - first, u) = (first * 256 - excluded_q8) / 256;
  }
  b.rows = b.row_weight.colwise().sum().transpose();
  return b;
}

}  // namespace lumavel::host
