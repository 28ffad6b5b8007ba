// The rotation identity's check, shared by the core and the lens tests:
// dF/dtheta from the derivative kernel against the finite difference of F
// under a +-0.5 deg turn of the cameras, at three places along the wall.
#pragma once
#include <cmath>

#include "lumavel/core/measurement.hpp"

namespace lumavel::test {

// Worst |dF/dtheta - finite difference| over the kernels and the places,
// relative to the rms of dF/dtheta at the place. `measure(x, theta)` gives
// the StereoMeasurement of the rig at body x, turned by theta.
template <typename Measure>
double worst_rotation_error(int kernels, Measure measure) {
  const double delta = 0.5 * 3.14159265358979323846 / 180;
  double worst = 0;
  for (double x : {0.0, 0.11, 0.37}) {
    const StereoMeasurement m0 = measure(x, 0.0);
    const StereoMeasurement mp = measure(x, delta);
    const StereoMeasurement mm = measure(x, -delta);
    double rms = 0;
    for (int k = 0; k < kernels; ++k) rms += std::pow(std::ldexp(m0.rot[k], -20), 2);
    rms = std::sqrt(rms / kernels);
    for (int k = 0; k < kernels; ++k) {
      const double fd = std::ldexp(mp.mid[k] - mm.mid[k], -28) / (2 * delta);
      worst = std::fmax(worst, std::fabs(fd - std::ldexp(m0.rot[k], -20)) / rms);
    }
  }
  return worst;
}

}  // namespace lumavel::test
