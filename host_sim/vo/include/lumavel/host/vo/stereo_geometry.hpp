// Calibrated two-view geometry of the rig: pixels to undistorted normalised
// rays, the epipolar test, triangulation in cam0's frame, and the
// projection of a cam0 ray into cam1 (the stereo search's first guess).
#pragma once
#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

#include "lumavel/host/vo/stereo_rig.hpp"

namespace lumavel::host::vo {

class StereoGeometry {
 public:
  explicit StereoGeometry(const StereoRig& rig);

  // Undistorted normalised image coordinates (x/z, y/z) of camera `cam`'s pixels.
  std::vector<cv::Point2d> normalise(int cam, const std::vector<cv::Point2f>& px) const;

  // Sampson distance of a cam0/cam1 ray pair to the rig's epipolar geometry,
  // in working pixels (mean focal length of the two cameras).
  double epipolar_px(const cv::Point2d& n0, const cv::Point2d& n1) const;

  // The points seen along both rays, in cam0's frame (linear triangulation,
  // cv::triangulatePoints). in_front[i] says whether point i has a positive
  // depth in both cameras; where it does not, the point is meaningless.
  std::vector<cv::Vec3d> triangulate(const std::vector<cv::Point2d>& n0, const std::vector<cv::Point2d>& n1,
                                     std::vector<uint8_t>& in_front) const;

  // Where cam1 sees the point at `depth` along cam0's ray `n0` (pixels,
  // through cam1's lens); depth <= 0 means infinitely far.
  cv::Point2f project_to_cam1(const cv::Point2d& n0, double depth) const;

  const StereoRig& rig() const { return rig_; }
  double focal_px(int cam) const { return 0.5 * (rig_.cam[cam].K(0, 0) + rig_.cam[cam].K(1, 1)); }

 private:
  StereoRig rig_;
  cv::Matx33d E_;  // essential matrix: n1^T E n0 = 0
  cv::Matx34d P1_;
};

}  // namespace lumavel::host::vo
