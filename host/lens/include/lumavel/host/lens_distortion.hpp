// Radial-tangential lens distortion (the OpenCV / EuRoC model) on normalised
// image coordinates x = (u - cu)/fu, y = (v - cv)/fv:
//   x_d = x (1 + k1 r^2 + k2 r^4) + 2 p1 x y + p2 (r^2 + 2 x^2)
//   y_d = y (1 + k1 r^2 + k2 r^4) + p1 (r^2 + 2 y^2) + 2 p2 x y
// The one inverse of it on the host: the renderer, the rig's column edges
// and the synthetic stream's barrel lens all undistort through here.
#pragma once
#include <array>

namespace lumavel::host {

// How far a lens this model holds moves a pixel from its pinhole place: the
// undistorted distance from the centre over the distorted one. A barrel lens
// of 120 deg (k1 -0.22, k2 0.05) reads 1.0-1.3, a strong pincushion (10 %)
// 0.9; k1 = 50 at 50 deg reads 0.34 and k1 = 1e10 a thousandth: one-to-one,
// but a wrong coefficient, not a lens.
constexpr double kLensMinRadialScale = 0.5, kLensMaxRadialScale = 4;

// Undistorted (x, y) of distorted (xd, yd) over the distances from the centre (1 at the centre).
double lens_radial_scale(double xd, double yd, double x, double y);
// Whether that ratio is one a lens gives (within the bounds above).
inline bool plausible_lens_scale(double scale) {
  return scale >= kLensMinRadialScale && scale <= kLensMaxRadialScale;
}

struct LensDistortion {
  std::array<double, 4> k{};  // k1, k2, p1, p2

  bool none() const { return k[0] == 0 && k[1] == 0 && k[2] == 0 && k[3] == 0; }
  // Undistorted -> distorted (normalised coordinates).
  void distort(double x, double y, double& xd, double& yd) const;
  // Distorted -> undistorted by Newton's method; false where no point maps
  // there one-to-one (the lens folds over, or the inverse diverges).
  bool undistort(double xd, double yd, double& x, double& y) const;
  // Whether the model is one-to-one around the undistorted point (x, y): its
  // Jacobian's determinant is positive (else the lens folds the image there).
  bool one_to_one_at(double x, double y) const;

 private:
  // d(xd, yd) / d(x, y) at an undistorted point (symmetric: d xd/dy = d yd/dx).
  void jacobian(double x, double y, double& dxx, double& dxy, double& dyy) const;
};

}  // namespace lumavel::host
