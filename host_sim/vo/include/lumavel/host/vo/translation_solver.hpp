// Frame-to-frame translation of cam0 with the rotation given (by the gyro):
// points triangulated at the previous frame must reproject onto their
// tracks in both cameras of the current frame. With the rotation known,
// one point seen by both cameras (4 equations) fixes the translation (3
// unknowns), so the RANSAC is a 1-point one: every point's hypothesis is
// scored (deterministic), the best one's inliers are refined by least
// squares on the reprojection error, with the inlier threshold tightened to
// three times the median residual (within [inlier_floor_px, inlier_px]).
#pragma once
#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

#include "lumavel/host/vo/stereo_rig.hpp"

namespace lumavel::host::vo {

struct MotionObservation {
  cv::Vec3d X;       // point in cam0's frame at the previous frame
  cv::Point2d n[2];  // its undistorted normalised coordinates now, cam0 and cam1
};

struct TranslationResult {
  bool ok = false;
  cv::Vec3d t;                // X_now = R X_prev + t, cam0 frame, m
  std::vector<uint8_t> inlier;   // per observation
  int inliers = 0;
  double rms_px = 0;          // reprojection rms of the inliers, working pixels
  double threshold_px = 0;    // the inlier threshold it ended with
};

// R: rotation of points from the previous cam0 frame to the current one.
// f_px: focal lengths of cam0 and cam1 (pixels per normalised unit), for
// the inlier thresholds (pixels).
TranslationResult solve_translation(const std::vector<MotionObservation>& obs, const cv::Matx33d& R,
                                    const StereoRig& rig, const double f_px[2], double inlier_px,
                                    double inlier_floor_px, int min_inliers);

}  // namespace lumavel::host::vo
