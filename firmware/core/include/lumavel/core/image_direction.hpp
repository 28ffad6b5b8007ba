// The direction of travel from each camera's own image motion.
//
// A translation dx moves a sideways camera's view by -dx / Z of yaw (looking
// left; +dx / Z looking right) whatever the depth Z > 0, so the image motion
// that the gyro's turn does not explain, read per camera over the kernels as
// a yaw, (dF - dtheta Rbar).Rbar / Rbar.Rbar summed over both cameras, has
// the sign of -V (looking left) at every depth: no stereo, no baseline. The
// stereo difference aliases on a texture that repeats within about 2h along
// the path (stripes, fences, tiles): there the differential and the time of
// flight can both read the wrong direction, and the time of flight can take
// an alias of the other direction for a track. This reading does not alias
// until the view moves half a texture period in a frame.
//
// Smoothed over kImageDirectionTau (with its scatter), it states a direction
// only beyond kImageDirectionMinRate and kImageDirectionSigmas of its scatter
// (fusion_params.hpp); the time of flight refuses tracks against it. Only the
// sign is used: the rate is V / Z, and Z is unknown.
//
// Formats: the rate and its mean in RateQ24 (held to +-64 rad/s), the
// scatter's variance in Q48 (below 2^62).
#pragma once
#include <cstdint>

#include "lumavel/core/config.hpp"
#include "lumavel/core/fixed.hpp"
#include "lumavel/core/measurement.hpp"

namespace lumavel {

class ImageDirection {
 public:
  void reset() { *this = ImageDirection{}; }
  // One interval, prev -> cur, that turned by dtheta (the gyro, offset
  // removed) in dt_ns > 0. look: +1 cameras looking left of the body x axis,
  // -1 right, 0 neither (no direction is ever stated).
  void update(const StereoMeasurement& prev, const StereoMeasurement& cur, AngleQ28 dtheta, int64_t dt_ns, int8_t look);
  // +1 moving along +x (body), -1 along -x, 0 unknown.
  int8_t direction() const { return direction_; }
  // A velocity beyond kImageDirectionFlagSpeed against the stated direction
  // (kStatusAgainstImages).
  bool against(SpeedQ16 v) const;

 private:
  RateQ24 mean_ = 0;  // smoothed image rate, signed as V
  int64_t var_ = 0;   // its scatter, Q48
  int8_t direction_ = 0;
};

// +1 cameras whose mean axis yaw looks left of body x, -1 right, 0 within
// asin(kImageDirectionMinLook) of the travel.
int8_t image_look(const CameraGeometry& cam0, const CameraGeometry& cam1);

}  // namespace lumavel
