#include "lumavel/host/vo/stereo_geometry.hpp"

#include <cmath>
#include <opencv2/calib3d.hpp>

namespace lumavel::host::vo {

StereoGeometry::StereoGeometry(const StereoRig& rig) : rig_(rig) {
  const cv::Vec3d& t = rig.t_10;
  const cv::Matx33d tx(0, -t[2], t[1], t[2], 0, -t[0], -t[1], t[0], 0);
  E_ = tx * rig.R_10;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) P1_(r, c) = rig.R_10(r, c);
    P1_(r, 3) = t[r];
  }
}

std::vector<cv::Point2d> StereoGeometry::normalise(int cam, const std::vector<cv::Point2f>& px) const {
  std::vector<cv::Point2d> out;
  if (px.empty()) return out;
  std::vector<cv::Point2d> in(px.begin(), px.end());
  const VoCamera& c = rig_.cam[cam];
  // More iterations than the default 5: wide barrel lenses need ~15 at the
  // image corners to converge to 1e-9.
  cv::undistortPoints(in, out, c.K, c.distortion, cv::noArray(), cv::noArray(),
                      cv::TermCriteria(cv::TermCriteria::COUNT | cv::TermCriteria::EPS, 30, 1e-12));
  return out;
}

double StereoGeometry::epipolar_px(const cv::Point2d& n0, const cv::Point2d& n1) const {
  const cv::Vec3d a(n0.x, n0.y, 1), b(n1.x, n1.y, 1);
  const cv::Vec3d ea = E_ * a, eb = E_.t() * b;
  const double e = b.dot(ea);
  const double den = ea[0] * ea[0] + ea[1] * ea[1] + eb[0] * eb[0] + eb[1] * eb[1];
  if (den <= 0) return 0;
  return std::sqrt(e * e / den) * 0.5 * (focal_px(0) + focal_px(1));
}

std::vector<cv::Vec3d> StereoGeometry::triangulate(const std::vector<cv::Point2d>& n0,
                                                   const std::vector<cv::Point2d>& n1,
                                                   std::vector<uint8_t>& in_front) const {
  const size_t n = n0.size();
  std::vector<cv::Vec3d> out(n, cv::Vec3d(0, 0, -1));
  in_front.assign(n, false);
  if (n == 0) return out;
  cv::Mat a(2, static_cast<int>(n), CV_64F), b(2, static_cast<int>(n), CV_64F), X;
  for (size_t i = 0; i < n; ++i) {
    const int c = static_cast<int>(i);
    a.at<double>(0, c) = n0[i].x;
    a.at<double>(1, c) = n0[i].y;
    b.at<double>(0, c) = n1[i].x;
    b.at<double>(1, c) = n1[i].y;
  }
  const cv::Matx34d P0(1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0);
  cv::triangulatePoints(P0, P1_, a, b, X);
  for (size_t i = 0; i < n; ++i) {
    const int c = static_cast<int>(i);
    const double w = X.at<double>(3, c);
    if (!(std::fabs(w) > 1e-300)) continue;
    const cv::Vec3d p(X.at<double>(0, c) / w, X.at<double>(1, c) / w, X.at<double>(2, c) / w);
    const cv::Vec3d p1 = rig_.R_10 * p + rig_.t_10;
    out[i] = p;
    in_front[i] = std::isfinite(p[2]) && p[2] > 0 && p1[2] > 0;
  }
  return out;
}

cv::Point2f StereoGeometry::project_to_cam1(const cv::Point2d& n0, double depth) const {
  const cv::Vec3d ray(n0.x, n0.y, 1);
  // Infinitely far: only the rotation between the cameras moves the point.
  const cv::Vec3d p1 = depth > 0 ? rig_.R_10 * (ray * depth) + rig_.t_10 : rig_.R_10 * ray;
  std::vector<cv::Point3d> obj{cv::Point3d(p1[0], p1[1], p1[2])};
  std::vector<cv::Point2d> img;
  const VoCamera& c = rig_.cam[1];
  cv::projectPoints(obj, cv::Vec3d(0, 0, 0), cv::Vec3d(0, 0, 0), c.K, c.distortion, img);
  return cv::Point2f(static_cast<float>(img[0].x), static_cast<float>(img[0].y));
}

}  // namespace lumavel::host::vo
