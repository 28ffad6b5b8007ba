#include "lumavel/host/lens_distortion.hpp"

#include <cmath>

namespace lumavel::host {
namespace {
constexpr int kMaxIterations = 20;      // ~10 suffice for a DAVIS-like barrel lens
constexpr double kSettled = 1e-14;      // normalised units
}  // namespace

void LensDistortion::distort(double x, double y, double& xd, double& yd) const {
  const double r2 = x * x + y * y;
  const double radial = 1 + k[0] * r2 + k[1] * r2 * r2;
  xd = x * radial + 2 * k[2] * x * y + k[3] * (r2 + 2 * x * x);
  yd = y * radial + k[2] * (r2 + 2 * y * y) + 2 * k[3] * x * y;
}

bool LensDistortion::undistort(double xd, double yd, double& x, double& y) const {
  x = xd;
  y = yd;
  if (none()) return true;
  for (int i = 0; i < kMaxIterations; ++i) {
    const double r2 = x * x + y * y;
    const double radial = 1 + k[0] * r2 + k[1] * r2 * r2;
    const double dx = 2 * k[2] * x * y + k[3] * (r2 + 2 * x * x);
    const double dy = k[2] * (r2 + 2 * y * y) + 2 * k[3] * x * y;
    const double nx = (xd - dx) / radial, ny = (yd - dy) / radial;
    const double step = std::fabs(nx - x) + std::fabs(ny - y);
    x = nx;
    y = ny;
    if (!std::isfinite(x) || !std::isfinite(y)) return false;
    if (step < kSettled) return true;
  }
  // Not settled: accept only if the forward model maps back closely.
  double cx, cy;
  distort(x, y, cx, cy);
  return std::fabs(cx - xd) + std::fabs(cy - yd) < 1e-9;
}

}  // namespace lumavel::host
