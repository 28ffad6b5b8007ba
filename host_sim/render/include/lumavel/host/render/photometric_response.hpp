// One camera's photometric response (PhotometricSpec). For the pixel in
// column c at normalised radius r from the image centre (pixel centres,
// r = 1 at the outer corner of the corner pixel), with radiance L:
//   s = gain AE(t) (1 + v1 r^2 + v2 r^4) (1 + prnu_p) (1 + colgain_c) L
//   y = 255 (max(s, 0) / 255)^gamma + black_level + dsnu_p + coloff_c
// y then gets pixel noise, rounding and clipping. The fixed patterns prnu_p,
// dsnu_p, colgain_c and coloff_c are Gaussian, drawn once per camera from the
// scenario seed (the same in every frame); AE(t) is the auto-exposure wander
// (AutoExposureSpec), independent per camera.
#pragma once
#include <cstdint>
#include <vector>

#include "lumavel/host/render/scenario.hpp"

namespace lumavel::host::render {

class CameraResponse {
 public:
  CameraResponse() = default;  // an ideal camera
  // Auto-exposure values cover [t_begin, t_end] (beyond: held).
  CameraResponse(const PhotometricSpec& spec, uint64_t seed, int cam, int width, int height, double t_begin,
                 double t_end);
  bool ideal() const { return ideal_; }
  const PhotometricSpec& spec() const { return spec_; }
  // gain x AE(t): the exposure multiplier of the whole image at time t.
  double exposure_gain(double t) const;
  // 1 + v1 r^2 + v2 r^4.
  double vignetting(double r) const;
  // Radiance (width*height, row-major, the size given) -> the camera's signal at time t.
  void apply(double t, std::vector<double>& image) const;

 private:
  PhotometricSpec spec_;
  bool ideal_ = true;
  std::vector<double> pixel_gain_;    // vignetting x PRNU x column gain
  std::vector<double> pixel_offset_;  // black level + DSNU + column offset
  double knot_t0_ = 0;
  std::vector<double> knots_;  // auto-exposure: unit normal values every interval_s
};

}  // namespace lumavel::host::render
