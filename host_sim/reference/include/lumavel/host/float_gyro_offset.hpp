// The double twin of firmware/core/gyro_offset.hpp (read the core's header
// for how stillness is judged, and why against a reference frame).
#pragma once
#include <cstdint>

#include "lumavel/host/float_measurement.hpp"

namespace lumavel::host {

struct FloatStillnessInput {
  const FloatStereoMeasurement* cur = nullptr;
  uint64_t t_ns = 0;
  double angle_raw = 0;  // raw gyro integral at t, rad
  bool textured = false;  // the observer could see motion in this interval
  double baseline = 0;        // m
  double still_distance = 0;  // m
  uint64_t still_min_ns = 0;  // the configuration's whole microseconds, in ns
};

class FloatGyroOffset {
 public:
  void update(const FloatStillnessInput& in);
  // A break in what the cameras witnessed: the reference is dropped, the
  // offset learned so far stays.
  void drop_reference() {
    have_ref_ = false;
    still_ = false;
  }
  double offset() const { return offset_; }  // rad/s
  bool still() const { return still_; }       // still for at least still_min
  // The offset's angle over dt seconds, to subtract from the raw gyro angle
  // (the core's take_angle_over, which carries its rounding; a double has none to carry).
  double angle_over(double dt) const { return offset_ * dt; }

 private:
  void anchor(const FloatStillnessInput& in);

  double offset_ = 0;
  bool still_ = false;
  bool have_ref_ = false;
  FloatStereoMeasurement ref_;
  uint64_t t_ref_ = 0;
  double angle_ref_ = 0;
};

}  // namespace lumavel::host
