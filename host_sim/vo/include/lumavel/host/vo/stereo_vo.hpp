// Keypoint stereo visual odometry, as a competent user builds it with
// OpenCV, reporting V along the body x axis:
//   1. corners in cam0 (Shi-Tomasi), matched into cam1 by pyramidal KLT,
//      checked against the calibrated epipolar geometry, triangulated;
//   2. each frame, every track followed by KLT in both cameras, and its
//      stereo match re-done from cam0 (so that its depth does not drift);
//   3. the rotation over the frame interval fixed by the gyro's integrated
//      yaw, the translation by 1-point RANSAC and least squares on the
//      reprojection errors in both cameras (translation_solver.hpp);
//   4. the body displacement along x over the interval / dt is the direct
//      measurement, filtered with lumavel's time constant;
//   5. too few inliers: V held, low-texture bit; tracks thinned out:
//      re-detection.
#pragma once
#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

#include "lumavel/host/vo/gyro_yaw.hpp"
#include "lumavel/host/vo/klt_frontend.hpp"
#include "lumavel/host/vo/stereo_geometry.hpp"
#include "lumavel/host/vo/stereo_rig.hpp"
#include "lumavel/host/vo/vo_params.hpp"

namespace lumavel::host::vo {

struct VoEstimate {
  uint64_t t_ns = 0;
  double v = 0;         // filtered V along body x, m/s
  double v_direct = 0;  // this interval's measurement (0 when none)
  double distance = 0;  // integral of V, m
  double heading = 0;   // integrated gyro yaw, rad, wrapped to [-pi, pi)
  uint16_t status = 0;  // lumavel::StatusFlag bits
  int tracks = 0;       // stereo tracks carried to the next frame
  int inliers = 0;      // tracks that agreed on this interval's motion
};

class StereoVo {
 public:
  explicit StereoVo(const StereoRig& rig, const VoParams& params = {});
  void push_gyro(uint64_t t_ns, double rate_z) { gyro_.push(t_ns, rate_z); }
  // Frames are rig.width x rig.height bytes each.
  VoEstimate step(uint64_t t_ns, const uint8_t* cam0, const uint8_t* cam1);

 private:
  struct Track {
    cv::Point2f px[2];  // cam0, cam1, working pixels
    cv::Vec3d X;        // triangulated, cam0 frame
  };
  // Measures the motion since the previous frame and moves the tracks to
  // the current one; false when it could not be measured.
  bool measure(double yaw, double dt, double& v_direct, int& inliers);
  // Stereo-matches current cam0 points into cam1 (from cam1 guesses) and
  // keeps those on the epipolar line and in front of both cameras.
  std::vector<Track> stereo_tracks(const std::vector<cv::Point2f>& p0, const std::vector<cv::Point2f>& guess1) const;
  void replenish();
  cv::Point2f cam1_guess(const cv::Point2d& n0, double depth) const { return geo_.project_to_cam1(n0, depth); }
  double median_depth() const;

  VoParams p_;
  StereoGeometry geo_;
  KltFrontend front_;
  GyroYaw gyro_;
  std::vector<Track> tracks_;
  double f_px_[2];
  uint64_t prev_t_ = 0;
  size_t frames_ = 0;
  double v_ = 0, distance_ = 0, heading_ = 0, since_start_ = 0;
  bool started_ = false;
};

}  // namespace lumavel::host::vo
