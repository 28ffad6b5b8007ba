// A distorted sensor image resampled onto the pinhole image of the same
// intrinsics, before binning (issue 11). A distorted column is not a meridian
// and a distorted row is not a line of one elevation: no table per column can
// make the column sums of a wide barrel lens behave like a pinhole's under
// rotation (the spin in place kept a spurious 0.16 m/s with per-column edges
// and elevation scales, against 0.04 through a pinhole). Undistorting every
// pixel first makes the working frame a pinhole frame, and every pinhole rule
// of the estimator applies to it as it is.
//
// Each output pixel (u, v) looks at normalised (x, y) = ((u - cu)/fu,
// (v - cv)/fv); the lens model distorts that to a sensor position, which is
// read bilinearly. The weights are kept in 1/256 (integer arithmetic, the
// same bytes on every machine). With a barrel lens (k1 < 0) every position
// falls inside the sensor; positions outside it (a pincushion lens at the
// corners) read the nearest edge pixel and are counted (outside()).
#pragma once
#include <cstdint>
#include <vector>

#include "lumavel/host/lens_distortion.hpp"

namespace lumavel::host {

struct PinholeIntrinsics {
  double fu, fv, cu, cv;  // pixels, the centre of pixel 0 at 0
};

class LensRemap {
 public:
  LensRemap(int width, int height, const PinholeIntrinsics& k, const LensDistortion& lens);
  // src and dst are width x height, row-major, no padding; they must differ.
  void apply(const uint8_t* src, uint8_t* dst) const;
  int width() const { return width_; }
  int height() const { return height_; }
  // Output pixels whose sensor position lies outside the sensor (clamped).
  int outside() const { return outside_; }

 private:
  struct Tap {
    uint32_t index;  // top-left source pixel
    uint8_t fx, fy;  // fractions towards the right and the lower neighbour, 1/256
    uint8_t dx, dy;  // 1 where that neighbour exists (0 at the last column / row)
  };
  int width_, height_;
  int outside_ = 0;
  std::vector<Tap> taps_;
};

}  // namespace lumavel::host
