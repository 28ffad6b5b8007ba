// Which way each camera's image moved between consecutive frames, compared
// between the two cameras. They look the same way (T_BS, checked by the rig
// rules), so any motion of the rig, travel along body x or a turn, moves both
// images the same way in body yaw: the image shift along u times the
// camera's u_sign (d(body yaw)/du from its T_BS) has the same sign in both.
// A camera whose image moves the other way on (nearly) every frame where
// both clearly moved is mirrored left-right, or upside down where its T_BS
// says upright: the estimator then runs with exit 0 and errors near 100 %
// (the stereo pair never agrees), flagged by nothing of its own. Swapped
// cameras (cam0's images in cam1) are not seen here: both images still move
// the same way (the estimates then have the wrong sign).
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace lumavel::host {

// A frame pair counts when both images moved by a whole working column or
// more, each shift matching the previous frame with a correlation of at
// least kMotionMinCorrelation (slower motion, a plain scene: not counted).
constexpr double kMotionMinCorrelation = 0.5;
// Opposite on at least this many such frames and this share of them: said.
// (On the rendered scenarios an intact rig was opposite on at most 1 frame
// of 362 (near_clutter at 40 columns), a mirrored one on every counted frame.)
constexpr size_t kMotionMinOppositeFrames = 20;
constexpr double kMotionOppositeShare = 0.9;

class MotionDirectionCheck {
 public:
  // `u_sign`: each camera's d(body yaw)/du sign (CameraModel::u_sign, u_sign_of).
  MotionDirectionCheck(int width, int height, int u_sign0, int u_sign1);
  // The next frame pair (width x height 8-bit each, the engine's frames).
  void add(const uint8_t* cam0, const uint8_t* cam1);
  size_t same() const { return same_; }          // frames where both moved the same way
  size_t opposite() const { return opposite_; }  // ... opposite ways
  // Opposite on kMotionMinOppositeFrames or more and on kMotionOppositeShare of the counted frames.
  bool mirrored() const;
  // Frames where camera c's image moved a working column or more and the
  // other camera's did not move at all (a flat view, or a frozen image).
  size_t alone(int c) const { return alone_[c]; }
  // Frames where either camera's image moved a working column or more.
  size_t moved() const { return same_ + opposite_ + alone_[0] + alone_[1]; }
  // The camera whose image stood still while the other's moved, on
  // kMotionMinOppositeFrames or more and on kMotionOppositeShare of the
  // frames where either moved: its lens is covered or blocked by something
  // plain, or it delivers one frame over and over, and the stereo difference
  // says nothing of V (the engines' low-texture test, on rms(F1 - F0), sees
  // the other camera's texture). -1: none.
  int still_camera() const;

 private:
  // The shift (columns, + towards larger u) from the previous profile to this one, 0 when not clear.
  int shift(const std::vector<double>& now, const std::vector<double>& before) const;
  int width_, height_;
  int u_sign_[2];
  std::vector<double> profile_[2], previous_[2];
  bool have_previous_ = false;
  size_t same_ = 0, opposite_ = 0;
  size_t alone_[2] = {0, 0};
};

// What a mirrored camera looks like, for run's warning and calibrate's
// refusal: "cam0's and cam1's images moved opposite ways on N of the M
// frames ... (ROOT/cam0/sensor.yaml, cam1/sensor.yaml)".
std::string opposite_motion_text(size_t opposite, size_t counted, const std::string& root);

// What a still camera looks like, for run's warning: "cam1's images did not
// move on N of the M frames where cam0's moved ...".
std::string still_camera_text(int still, size_t alone, size_t counted, const std::string& root);

}  // namespace lumavel::host
