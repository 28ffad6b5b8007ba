// The stereo rig as the VO sees it, from the two cameras' sensor.yaml: each
// camera's intrinsics scaled to the working resolution, its lens
// (radial-tangential), its pose in the body frame, and the pose of cam1
// relative to cam0. Nothing is assumed about which camera is ahead, which
// side they look to, or their alignment: all of it is read from T_BS.
#pragma once
#include <opencv2/core.hpp>
#include <string>

#include "lumavel/host/recording.hpp"

namespace lumavel::host::vo {

// Smallest working image the VO accepts (the KLT window and a two-level
// pyramid need this much); line-scan sensors are refused.
constexpr int kMinVoWidth = 16, kMinVoHeight = 12;

struct VoCamera {
  cv::Matx33d K;        // working-resolution pixels, centre of pixel 0 = 0
  cv::Vec4d distortion;  // k1, k2, p1, p2 (radial-tangential, on normalised coordinates)
  cv::Matx33d R_BC;     // camera axes in the body frame: X_B = R_BC X_C + c_B
  cv::Vec3d c_B;        // optical centre in the body frame, m
  double hfov = 0;      // horizontal field of view, rad (pinhole part)
};

struct StereoRig {
  int width = 0, height = 0;  // working resolution of both cameras
  VoCamera cam[2];
  cv::Matx33d R_10;  // X_C1 = R_10 X_C0 + t_10
  cv::Vec3d t_10;
  double baseline = 0;       // |c1 - c0|, m
  double frame_period = 0;   // s, median frame interval of the recording
};

// Throws RecordingError naming the sensor.yaml and the rule when the rig
// cannot do stereo: cameras less than 1 mm apart, views that do not overlap,
// a line-scan or too small image, a rotation that is not one, a working size
// larger than the sensor. `ignore_distortion` reads the lenses as pinhole.
StereoRig make_stereo_rig(const Recording& rec, int width, int height, bool ignore_distortion = false);

}  // namespace lumavel::host::vo
