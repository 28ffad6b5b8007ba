#include "lumavel/host/lens_distortion.hpp"

#include <cmath>

namespace lumavel::host {
namespace {
constexpr int kMaxIterations = 50;      // Newton: 3-6 from the distorted point on the scenes' lenses
constexpr int kMaxHalvings = 30;
constexpr double kSettled = 1e-14;      // |distort(x, y) - (xd, yd)|, normalised units
constexpr double kInverseTolerance = 1e-9;  // the forward model must map back this closely
}  // namespace

double lens_radial_scale(double xd, double yd, double x, double y) {
  const double rd = std::hypot(xd, yd);
  return rd > 0 ? std::hypot(x, y) / rd : 1.0;
}

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
  // Newton on distort(x, y) = (xd, yd), each step halved until it brings the
  // point closer. (A fixed-point iteration of the inverse, the first version,
  // did not settle in the corners of strong wide lenses that are one-to-one:
  // k1 -0.22, k2 0.05 at hfov 120 deg.)
  double ex = 0, ey = 0;
  auto miss = [&](double px, double py) {
    double fx, fy;
    distort(px, py, fx, fy);
    ex = fx - xd;
    ey = fy - yd;
    return std::fabs(ex) + std::fabs(ey);
  };
  double err = miss(x, y);
  for (int i = 0; i < kMaxIterations && err >= kSettled; ++i) {
    double a, b, d;
    jacobian(x, y, a, b, d);
    const double det = a * d - b * b;
    if (!(det > 0)) return false;  // folded here: no one-to-one inverse
    const double sx = (d * ex - b * ey) / det, sy = (a * ey - b * ex) / det;
    double t = 1;
    const double ox = x, oy = y, old = err, oex = ex, oey = ey;
    for (int halvings = 0; halvings < kMaxHalvings; ++halvings, t /= 2) {
      x = ox - t * sx;
      y = oy - t * sy;
      err = miss(x, y);
      if (err < old) break;
    }
    if (!(err < old)) {  // no step helps: stuck
      x = ox;
      y = oy;
      err = old;
      ex = oex;
      ey = oey;
      break;
    }
  }
  if (!std::isfinite(x) || !std::isfinite(y)) return false;
  return one_to_one_at(x, y) && err < kInverseTolerance;
}

bool LensDistortion::one_to_one_at(double x, double y) const {
  double a, b, d;
  jacobian(x, y, a, b, d);
  return a * d - b * b > 0;
}

void LensDistortion::jacobian(double x, double y, double& dxx, double& dxy, double& dyy) const {
  const double r2 = x * x + y * y;
  const double radial = 1 + k[0] * r2 + k[1] * r2 * r2;
  const double slope = k[0] + 2 * k[1] * r2;  // d radial / d r2
  dxx = radial + 2 * x * x * slope + 2 * k[2] * y + 6 * k[3] * x;
  dxy = 2 * x * y * slope + 2 * k[2] * x + 2 * k[3] * y;
  dyy = radial + 2 * y * y * slope + 6 * k[2] * y + 2 * k[3] * x;
}

}  // namespace lumavel::host
