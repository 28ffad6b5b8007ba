#include "lumavel/host/vo/klt_frontend.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <opencv2/video/tracking.hpp>

namespace lumavel::host::vo {
namespace {

// KLT window: 7 px (the smallest that holds a corner's 2-D structure at
// 40x30), growing with the image beyond 80 columns so that it covers about
// the same part of the view, up to 21 px (beyond that the window straddles
// depth edges and gains little accuracy).
int window_for(int width) {
  int w = static_cast<int>(std::lround(width / 12.0));
  w = std::clamp(w, 7, 21);
  return w | 1;  // odd: centred on the point
}

// Pyramid: as many halvings as leave the top level at least two windows
// high. The search then reaches about window/2 * 2^levels pixels around its
// start; a smaller top level holds too few texture periods per window and
// aliases (at 40x30 a third level, 10x8, made the tracks on the paper's
// sinusoid wall jump periods: E 18 % instead of 0.3 %).
int levels_for(int width, int height, int window) {
  int levels = 0;
  for (double s = std::min(width, height) / 2.0; s >= 2 * window && levels < 6; s /= 2) ++levels;
  return levels;
}

}  // namespace

KltFrontend::KltFrontend(int width, int height, const VoParams& params)
    : width_(width), height_(height), p_(params) {
  window_ = window_for(width);
  levels_ = levels_for(width, height, window_);
  // Corners at least 1/32 of the width apart (2 px minimum): ~30 across
  // the view at any resolution.
  spacing_ = std::max(2.0, width / 32.0);
  // OpenCV's LK compares the smaller eigenvalue of the window's gradient
  // matrix, per pixel, with Scharr derivatives (32x the gradient) scaled by
  // 2^-20: a gradient of g gray levels per pixel reads g^2 / 1024.
  min_eig_ = p_.min_gradient * p_.min_gradient / 1024.0;
}

void KltFrontend::push_frames(const uint8_t* cam0, const uint8_t* cam1) {
  const uint8_t* src[2] = {cam0, cam1};
  for (int c = 0; c < 2; ++c) {
    if (have_frame_) std::swap(prev_pyr_[c], pyr_[c]);
    image_[c] = cv::Mat(height_, width_, CV_8UC1, const_cast<uint8_t*>(src[c])).clone();
    pyr_[c].clear();
    cv::buildOpticalFlowPyramid(image_[c], pyr_[c], cv::Size(window_, window_), levels_, true);
  }
  have_prev_ = have_frame_;
  have_frame_ = true;
}

double KltFrontend::mean_level(int cam) const { return have_frame_ ? cv::mean(image_[cam])[0] : 0.0; }

std::vector<cv::Point2f> KltFrontend::lk(const std::vector<cv::Mat>& a, const std::vector<cv::Mat>& b,
                                         const std::vector<cv::Point2f>& from, const std::vector<cv::Point2f>* guess,
                                         std::vector<uint8_t>& ok) const {
  ok.assign(from.size(), false);
  std::vector<cv::Point2f> to = guess ? *guess : from, back = from;
  if (from.empty()) return to;
  const cv::TermCriteria stop(cv::TermCriteria::COUNT | cv::TermCriteria::EPS, p_.klt_iterations, p_.klt_epsilon_px);
  const cv::Size win(window_, window_);
  std::vector<uchar> st, st_back;
  std::vector<float> err;
  cv::calcOpticalFlowPyrLK(a, b, from, to, st, err, win, levels_, stop, cv::OPTFLOW_USE_INITIAL_FLOW, min_eig_);
  cv::calcOpticalFlowPyrLK(b, a, to, back, st_back, err, win, levels_, stop, cv::OPTFLOW_USE_INITIAL_FLOW, min_eig_);
  const double fb2 = p_.max_forward_backward_px * p_.max_forward_backward_px;
  for (size_t i = 0; i < from.size(); ++i) {
    const cv::Point2f d = back[i] - from[i];
    const double x = static_cast<double>(to[i].x), y = static_cast<double>(to[i].y);
    ok[i] = st[i] && st_back[i] && static_cast<double>(d.dot(d)) <= fb2 && x >= 0 && y >= 0 &&
            x <= width_ - 1 && y <= height_ - 1;
  }
  return to;
}

std::vector<cv::Point2f> KltFrontend::track(int cam, const std::vector<cv::Point2f>& prev, std::vector<uint8_t>& ok) const {
  if (!have_prev_) {
    ok.assign(prev.size(), false);
    return prev;
  }
  return lk(prev_pyr_[cam], pyr_[cam], prev, nullptr, ok);
}

std::vector<cv::Point2f> KltFrontend::match_stereo(const std::vector<cv::Point2f>& p0,
                                                   const std::vector<cv::Point2f>& guess,
                                                   std::vector<uint8_t>& ok) const {
  return lk(pyr_[0], pyr_[1], p0, &guess, ok);
}

std::vector<cv::Point2f> KltFrontend::detect(const std::vector<cv::Point2f>& existing, int count) const {
  std::vector<cv::Point2f> corners;
  if (count <= 0 || !have_frame_) return corners;
  cv::Mat mask(height_, width_, CV_8UC1, cv::Scalar(255));
  const int r = static_cast<int>(std::ceil(spacing_));
  for (const cv::Point2f& p : existing) cv::circle(mask, cv::Point(cvRound(p.x), cvRound(p.y)), r, cv::Scalar(0), -1);
  cv::goodFeaturesToTrack(image_[0], corners, count, p_.corner_quality, spacing_, mask, 3, false);
  return corners;
}

}  // namespace lumavel::host::vo
