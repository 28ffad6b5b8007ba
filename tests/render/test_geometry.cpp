// Projection geometry: where a known world edge lands in the rendered image
// (left- and right-looking rigs, cam0/cam1 ahead, misaligned cam1, turned
// body) and the signs of T_BS. The expected pixel positions are written out
// with explicit trigonometry, independent of the renderer's matrices.
#include <CppUTest/TestHarness.h>

#include <cmath>

#include "lumavel/host/render/frame_renderer.hpp"
#include "lumavel/host/render/scene.hpp"
#include "lumavel/host/render/sensor_synthesis.hpp"
#include "render_test_support.hpp"

using namespace lumavel::host::render;
using namespace lumavel::host::render::test;

namespace {
constexpr double kPi = 3.14159265358979323846;

double edge_v_from_top(const std::vector<double>& img, int w, int h, int col) {
  double sum = 0;
  for (int r = 0; r < h; ++r) sum += img[static_cast<size_t>(r * w + col)] / 255.0;
  return sum - 0.5;
}

}  // namespace

TEST_GROUP(Geometry){};

TEST(Geometry, LeftLookingCamerasSeeForwardToTheRight) {
  // Wall at y = 2 m covering x <= 0.3 m: its right edge is at
  // u = cu + fu (0.3 - x_cam) / 2 for cam0 (x = -h/2) and cam1 (x = +h/2).
  Scenario s = empty_scenario(64, 48);
  s.camera.baseline_m = 0.1;
  s.planes.push_back(wall_at(2.0, -20, 0.3, -20, 20, uniform(255)));
  const Pinhole p = pinhole_from_fov(64, 48, 50, 40);
  for (int cam = 0; cam < 2; ++cam) {
    const double x_cam = cam == 0 ? -0.05 : 0.05;
    const auto img = radiance(s, cam);
    DOUBLES_EQUAL(p.cu + p.fu * (0.3 - x_cam) / 2.0, edge_u_from_left(img, 64, 10), 1e-6);
  }
}

TEST(Geometry, Cam0AheadSwapsTheOpticalCentres) {
  Scenario s = empty_scenario(64, 48);
  s.camera.baseline_m = 0.1;
  s.camera.cam1_ahead = false;
  s.planes.push_back(wall_at(2.0, -20, 0.3, -20, 20, uniform(255)));
  const Pinhole p = pinhole_from_fov(64, 48, 50, 40);
  DOUBLES_EQUAL(p.cu + p.fu * (0.3 - 0.05) / 2.0, edge_u_from_left(radiance(s, 0), 64, 10), 1e-6);
  DOUBLES_EQUAL(p.cu + p.fu * (0.3 + 0.05) / 2.0, edge_u_from_left(radiance(s, 1), 64, 10), 1e-6);
}

TEST(Geometry, ImageDownIsWorldDown) {
  // Wall covering z >= -0.25 m at 2 m: its bottom edge is at v = cv + fv 0.25 / 2.
  Scenario s = empty_scenario(64, 48);
  s.planes.push_back(wall_at(2.0, -20, 20, -0.25, 20, uniform(255)));
  const Pinhole p = pinhole_from_fov(64, 48, 50, 40);
  DOUBLES_EQUAL(p.cv + p.fv * 0.25 / 2.0, edge_v_from_top(radiance(s, 0), 64, 48, 30), 1e-6);
}

TEST(Geometry, RightLookingCamerasSeeBackwardToTheRight) {
  // Wall at y = -2 m covering x >= -0.3 m: seen looking right, +x is to the
  // image left, so the wall fills the left part up to u = cu + fu (x_cam + 0.3) / 2.
  Scenario s = empty_scenario(64, 48);
  s.camera.look = LookSide::Right;
  s.camera.baseline_m = 0.1;
  s.planes.push_back(wall_at(-2.0, -0.3, 20, -20, 20, uniform(255)));
  const Pinhole p = pinhole_from_fov(64, 48, 50, 40);
  for (int cam = 0; cam < 2; ++cam) {
    const double x_cam = cam == 0 ? -0.05 : 0.05;
    DOUBLES_EQUAL(p.cu + p.fu * (x_cam + 0.3) / 2.0, edge_u_from_left(radiance(s, cam), 64, 10), 1e-6);
  }
}

TEST(Geometry, MisalignedCam1IsYawedCounterClockwise) {
  // cam1 yawed by +3 deg (CCW) looks slightly backwards: its right axis is
  // (cos a, sin a, 0) and its optical axis (-sin a, cos a, 0).
  const double a = 3.0 * kPi / 180;
  Scenario s = empty_scenario(64, 48);
  s.camera.baseline_m = 0.1;
  s.camera.misalignment_deg = 3.0;
  s.planes.push_back(wall_at(2.0, -20, 0.3, -20, 20, uniform(255)));
  const Pinhole p = pinhole_from_fov(64, 48, 50, 40);
  const double dx = 0.3 - 0.05, dy = 2.0;
  const double xc = dx * std::cos(a) + dy * std::sin(a);
  const double zc = -dx * std::sin(a) + dy * std::cos(a);
  // A level camera sees the vertical edge as a vertical line: same u on every row.
  // The wall is slanted by 3 deg for cam1: a pixel weights its patch
  // uniformly on the plane, not on the image, which moves the edge pixel's
  // covered fraction by (depth change across the pixel) * f (1 - f), about
  // 5e-4 px here; an aligned camera (above) is exact.
  const auto img = radiance(s, 1);
  DOUBLES_EQUAL(p.cu + p.fu * xc / zc, edge_u_from_left(img, 64, 23), 1e-3);
  DOUBLES_EQUAL(p.cu + p.fu * xc / zc, edge_u_from_left(img, 64, 3), 1e-3);
}

TEST(Geometry, TurnedBodyTurnsTheView) {
  // Body at (1, 2) facing +y (heading 90 deg): left-looking cameras look
  // towards -x, image right = body forward = +y. Wall at x = -1 covering y <= 2.4.
  Scenario s = empty_scenario(64, 48);
  s.camera.baseline_m = 0.1;
  s.trajectory.x0 = 1;
  s.trajectory.y0 = 2;
  s.trajectory.heading0_deg = 90;
  PlaneSpec w;
  w.from[0] = -1;
  w.from[1] = -20;
  w.to[0] = -1;
  w.to[1] = 2.4;
  w.z_min = -20;
  w.z_max = 20;
  w.pattern = uniform(255);
  s.planes.push_back(w);
  const Pinhole p = pinhole_from_fov(64, 48, 50, 40);
  // cam0 sits at y = 2 - 0.05, 2 m from the wall.
  DOUBLES_EQUAL(p.cu + p.fu * (2.4 - 1.95) / 2.0, edge_u_from_left(radiance(s, 0), 64, 10), 1e-6);
}

TEST(Geometry, TBSSignsFollowTheContract) {
  Scenario s = empty_scenario(40, 30);
  s.camera.baseline_m = 0.08;
  s.camera.misalignment_deg = 1.6;
  const StereoRig left(s.camera);
  const auto c0 = camera_sensor(s, left, 0), c1 = camera_sensor(s, left, 1);
  // Row-major 4x4: column 2 (optical axis) of a left-looking camera is +y,
  // column 1 (image down) is -z, column 0 (image right) is +x.
  DOUBLES_EQUAL(1.0, c0.T_BS[6], 1e-12);
  DOUBLES_EQUAL(-1.0, c0.T_BS[9], 1e-12);
  DOUBLES_EQUAL(1.0, c0.T_BS[0], 1e-12);
  // Baseline cam0 -> cam1 along +x (cam1 ahead), h = 8 cm.
  DOUBLES_EQUAL(0.08, c1.T_BS[3] - c0.T_BS[3], 1e-12);
  DOUBLES_EQUAL(0.0, c0.T_BS[7], 1e-12);
  DOUBLES_EQUAL(0.0, c0.T_BS[11], 1e-12);
  DOUBLES_EQUAL(1.0, c0.T_BS[15], 0);
  // Misalignment = yaw from cam0's optical axis to cam1's, CCW positive.
  const double yaw = std::atan2(c0.T_BS[2] * c1.T_BS[6] - c0.T_BS[6] * c1.T_BS[2],
                                c0.T_BS[2] * c1.T_BS[2] + c0.T_BS[6] * c1.T_BS[6]);
  DOUBLES_EQUAL(1.6 * kPi / 180, yaw, 1e-12);

  s.camera.look = LookSide::Right;
  s.camera.cam1_ahead = false;
  const StereoRig right(s.camera);
  const auto r0 = camera_sensor(s, right, 0), r1 = camera_sensor(s, right, 1);
  DOUBLES_EQUAL(-1.0, r0.T_BS[6], 1e-12);   // optical axis -y
  DOUBLES_EQUAL(-1.0, r0.T_BS[0], 1e-12);   // image right = backward
  DOUBLES_EQUAL(-1.0, r0.T_BS[9], 1e-12);   // image down = -z
  DOUBLES_EQUAL(-0.08, r1.T_BS[3] - r0.T_BS[3], 1e-12);
}

TEST(Geometry, IntrinsicsFromFieldOfView) {
  const Pinhole p = pinhole_from_fov(640, 480, 50, 40);
  DOUBLES_EQUAL(320.0 / std::tan(25 * kPi / 180), p.fu, 1e-9);
  DOUBLES_EQUAL(240.0 / std::tan(20 * kPi / 180), p.fv, 1e-9);
  DOUBLES_EQUAL(319.5, p.cu, 0);
  DOUBLES_EQUAL(239.5, p.cv, 0);
}
