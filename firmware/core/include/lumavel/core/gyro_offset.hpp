// Learns the gyro's zero-rate offset while the images show the rig standing
// still, and keeps tracking it (MEMS offsets drift with temperature).
//
// Stillness is judged from the images alone, against a reference frame: the
// change since the reference, read as a translation, stays below
// `still_distance`, both the stereo mean's and each camera's own (a texture
// that repeats every 2h leaves the mean still while the rig moves). Any
// rotation or translation moves the images, so only a rig at rest passes
// (untextured scenes are excluded). Comparing with a fixed
// reference rather than frame to frame keeps pixel noise from adding up: the
// noise of one difference is ~0.5 mm at 40x30 while real motion keeps growing.
// Once a still period lasts `still_min_us`, the offset is the mean gyro rate
// since the reference, updated on every further still frame; after 20 s the
// reference is renewed so that the offset follows drift. Any break in the
// frames drops the reference (drop_reference): the mean rate over a gap,
// turning included, must never become the offset.
#pragma once
#include <cstdint>

#include "lumavel/core/fixed.hpp"
#include "lumavel/core/measurement.hpp"

namespace lumavel {

struct StillnessInput {
  const StereoMeasurement* cur;
  uint64_t t_ns;
  int64_t angle_raw;  // raw gyro integral at t, Q28
  bool textured;      // the observer could see motion in this interval
  LengthQ24 baseline;
  LengthQ24 still_distance;
  uint32_t still_min_us;
};

class GyroOffset {
 public:
  void reset() { *this = GyroOffset{}; }
  void update(const StillnessInput& in);
  // A break in what the cameras witnessed (frame gap, restart, dark or
  // duplicated frames, gyro not covering the interval): stillness must be
  // seen frame by frame, so the reference from before the break is dropped
  // and the next update starts a new one. The offset learned so far stays.
  void drop_reference() {
    have_ref_ = false;
    still_ = false;
  }
  RateQ24 offset() const { return offset_; }
  bool still() const { return still_; }  // still for at least still_min
  // The offset's angle over the next dt (Q28), to subtract from the raw gyro
  // angle. The rounding remainder is carried to the next call, so that a day
  // of frame intervals adds no rounding up (0.3 LSB a frame at 60 Hz would be
  // 6e-3 rad a day).
  int64_t take_angle_over(int64_t dt_ns);

 private:
  void anchor(const StillnessInput& in);
  bool camera_moved(const StillnessInput& in, int64_t den) const;

  RateQ24 offset_ = 0;
  bool still_ = false;
  bool have_ref_ = false;
  StereoMeasurement ref_{};
  uint64_t t_ref_ = 0;
  int64_t angle_ref_ = 0;
  int64_t angle_rem_ = 0;  // carried remainder of take_angle_over, [0, 62500000)
};

}  // namespace lumavel
