// Stereo geometry and the translation solver on exact synthetic data: a
// point projected through both lenses comes back from triangulation, and
// the solver finds a known motion among outliers.
#include <opencv2/calib3d.hpp>
#include <vector>

#include "lumavel/host/vo/stereo_geometry.hpp"
#include "lumavel/host/vo/translation_solver.hpp"
#include "recording_fixture.hpp"
// CppUTest last: its leak-detector macros redefine new.
#include "CppUTest/TestHarness.h"

using namespace lumavel::host;
using namespace lumavel::host::vo;

namespace {

StereoRig test_rig() {
  Recording r;
  r.root = "/data/rec";
  r.cam[0] = fixture::left_camera(160, 120, 0.04);  // cam0 ahead this time
  r.cam[1] = fixture::left_camera(160, 120, -0.04);
  // cam1 yawed by 1.5 deg about body z (misaligned rig).
  const double a = 1.5 * M_PI / 180, c = std::cos(a), s = std::sin(a);
  const cv::Matx33d Rz(c, -s, 0, s, c, 0, 0, 0, 1), R_BC(1, 0, 0, 0, 0, 1, 0, -1, 0);
  const cv::Matx33d R = Rz * R_BC;
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) r.cam[1].T_BS[static_cast<size_t>(4 * i + k)] = R(i, k);
  r.frame_period_s = 0.01;
  return make_stereo_rig(r, 160, 120);
}

// Pixel of a cam0-frame point in camera `cam` (through its lens).
cv::Point2f pixel(const StereoRig& rig, int cam, const cv::Vec3d& X0) {
  const cv::Vec3d X = cam == 0 ? X0 : rig.R_10 * X0 + rig.t_10;
  std::vector<cv::Point3d> obj{cv::Point3d(X[0], X[1], X[2])};
  std::vector<cv::Point2d> img;
  cv::projectPoints(obj, cv::Vec3d(0, 0, 0), cv::Vec3d(0, 0, 0), rig.cam[cam].K, rig.cam[cam].distortion, img);
  return cv::Point2f(static_cast<float>(img[0].x), static_cast<float>(img[0].y));
}

}  // namespace

TEST_GROUP(VoGeometry){};

TEST(VoGeometry, TriangulatesWhatBothLensesSee) {
  const StereoRig rig = test_rig();
  const StereoGeometry geo(rig);
  std::vector<cv::Vec3d> truth = {{0.3, -0.2, 2.0}, {-0.5, 0.3, 0.6}, {0.05, 0.01, 9.0}};
  std::vector<cv::Point2f> p0, p1;
  for (const cv::Vec3d& X : truth) {
    p0.push_back(pixel(rig, 0, X));
    p1.push_back(pixel(rig, 1, X));
  }
  const std::vector<cv::Point2d> n0 = geo.normalise(0, p0), n1 = geo.normalise(1, p1);
  std::vector<uint8_t> in_front;
  const std::vector<cv::Vec3d> X = geo.triangulate(n0, n1, in_front);
  for (size_t i = 0; i < truth.size(); ++i) {
    CHECK(in_front[i]);
    // Pixels are floats: ~1e-5 px of rounding, i.e. ~1e-4 relative depth at 9 m.
    DOUBLES_EQUAL(0, cv::norm(X[i] - truth[i]) / truth[i][2], 2e-4);
    DOUBLES_EQUAL(0, geo.epipolar_px(n0[i], n1[i]), 1e-3);
    const cv::Point2f guess = geo.project_to_cam1(n0[i], truth[i][2]);
    DOUBLES_EQUAL(0, cv::norm(guess - p1[i]), 1e-3);
  }
  // The same pair swapped between the cameras is not a stereo match: it is
  // off the epipolar line or behind a camera.
  std::vector<uint8_t> swapped_in_front;
  geo.triangulate(n1, n0, swapped_in_front);
  for (size_t i = 0; i < 2; ++i) CHECK(!swapped_in_front[i] || geo.epipolar_px(n1[i], n0[i]) > 1);
}

TEST(VoGeometry, SolverFindsTheMotionAmongOutliers) {
  const StereoRig rig = test_rig();
  const StereoGeometry geo(rig);
  const double yaw = 0.01, c = std::cos(yaw), s = std::sin(yaw);
  const cv::Matx33d R(c, 0, s, 0, 1, 0, -s, 0, c);  // some rotation of the points in cam0's frame
  const cv::Vec3d t(-0.012, 0.001, 0.003);
  std::vector<MotionObservation> obs;
  for (int i = 0; i < 40; ++i) {
    const cv::Vec3d X(-0.6 + 0.03 * i, 0.2 * std::sin(i), 1.5 + 0.05 * (i % 7));
    const cv::Vec3d Y = R * X + t;
    MotionObservation o;
    o.X = X;
    for (int cam = 0; cam < 2; ++cam) {
      std::vector<cv::Point2f> px{pixel(rig, cam, Y)};
      if (i % 10 == 3) px[0].x += 3.0f;  // four gross outliers
      o.n[cam] = geo.normalise(cam, px)[0];
    }
    obs.push_back(o);
  }
  const double f[2] = {geo.focal_px(0), geo.focal_px(1)};
  const TranslationResult r = solve_translation(obs, R, rig, f, 0.5, 0.05, 8);
  CHECK(r.ok);
  LONGS_EQUAL(36, r.inliers);
  for (int i = 0; i < 40; ++i) CHECK_EQUAL(i % 10 != 3, r.inlier[static_cast<size_t>(i)] != 0);
  DOUBLES_EQUAL(0, cv::norm(r.t - t), 1e-5);
  // Too few observations: no answer rather than a guess.
  const std::vector<MotionObservation> few(obs.begin(), obs.begin() + 5);
  CHECK(!solve_translation(few, R, rig, f, 0.5, 0.05, 8).ok);
}
