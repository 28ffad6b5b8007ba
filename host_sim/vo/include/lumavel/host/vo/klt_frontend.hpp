// The image side of the VO: Shi-Tomasi corners in cam0, pyramidal
// Lucas-Kanade to follow them into cam1 (stereo) and into the next frame
// (temporal), every track checked forward and backward. Window, pyramid and
// corner spacing are sized for the working image (see the .cpp).
#pragma once
#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

#include "lumavel/host/vo/vo_params.hpp"

namespace lumavel::host::vo {

class KltFrontend {
 public:
  KltFrontend(int width, int height, const VoParams& params);

  // The next frame pair (copied); the current one becomes the previous.
  void push_frames(const uint8_t* cam0, const uint8_t* cam1);
  bool has_previous() const { return have_prev_; }
  // Mean gray level of the current image of `cam`.
  double mean_level(int cam) const;

  // Follows camera `cam`'s points from the previous frame into the current
  // one; ok[i] is false for a point lost, untextured or inconsistent back.
  std::vector<cv::Point2f> track(int cam, const std::vector<cv::Point2f>& prev, std::vector<uint8_t>& ok) const;
  // Finds current cam0 points in the current cam1 image, starting from `guess`.
  std::vector<cv::Point2f> match_stereo(const std::vector<cv::Point2f>& p0, const std::vector<cv::Point2f>& guess,
                                        std::vector<uint8_t>& ok) const;
  // Up to `count` new corners in the current cam0 image, at least the
  // corner spacing away from `existing`.
  std::vector<cv::Point2f> detect(const std::vector<cv::Point2f>& existing, int count) const;

  int window() const { return window_; }
  int levels() const { return levels_; }
  double corner_spacing() const { return spacing_; }

 private:
  // Lucas-Kanade from pyramid a to b, then back; a point passes when it
  // stays inside b and comes back within the forward-backward tolerance.
  std::vector<cv::Point2f> lk(const std::vector<cv::Mat>& a, const std::vector<cv::Mat>& b,
                              const std::vector<cv::Point2f>& from, const std::vector<cv::Point2f>* guess,
                              std::vector<uint8_t>& ok) const;

  int width_, height_;
  VoParams p_;
  int window_, levels_;
  double spacing_;
  double min_eig_;  // Lucas-Kanade's minEigThreshold for p_.min_gradient
  cv::Mat image_[2];
  std::vector<cv::Mat> pyr_[2], prev_pyr_[2];
  bool have_frame_ = false, have_prev_ = false;
};

}  // namespace lumavel::host::vo
