// Radial-tangential lens distortion (the OpenCV / EuRoC model) on normalised
// image coordinates x = (u - cu)/fu, y = (v - cv)/fv:
//   x_d = x (1 + k1 r^2 + k2 r^4) + 2 p1 x y + p2 (r^2 + 2 x^2)
//   y_d = y (1 + k1 r^2 + k2 r^4) + p1 (r^2 + 2 y^2) + 2 p2 x y
// The one inverse of it on the host: the renderer, the rig's column edges
// and the synthetic stream's barrel lens all undistort through here.
#pragma once
#include <array>

namespace lumavel::host {

struct LensDistortion {
  std::array<double, 4> k{};  // k1, k2, p1, p2

  bool none() const { return k[0] == 0 && k[1] == 0 && k[2] == 0 && k[3] == 0; }
  // Undistorted -> distorted (normalised coordinates).
  void distort(double x, double y, double& xd, double& yd) const;
  // Distorted -> undistorted by fixed-point iteration of the inverse; false
  // if it did not settle (coefficients not invertible there).
  bool undistort(double xd, double yd, double& x, double& y) const;
};

}  // namespace lumavel::host
