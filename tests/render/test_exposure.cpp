// Exposure blur: the timestamp is the middle of the exposure, and a moving
// edge is spread over the distance it travels during the exposure.
#include <CppUTest/TestHarness.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "lumavel/host/render/frame_renderer.hpp"
#include "lumavel/host/render/scene.hpp"
#include "render_test_support.hpp"

using namespace lumavel::host::render;
using namespace lumavel::host::render::test;

namespace {

// A camera moving forward at `speed` along a wall 2 m away whose left part
// (s < 10 m) is white and right part black; the boundary sits at x = 0.
Scenario moving_edge(double speed, double exposure) {
  Scenario s = empty_scenario(80, 4, speed);
  s.camera.baseline_m = 0;
  s.camera.rate_hz = 30;
  s.camera.exposure_frames = exposure;
  s.trajectory.x0 = 0;
  s.planes.push_back(wall_at(2.0, -10, 10, -20, 5, checker(10, 0, 255)));
  return s;
}

std::vector<double> row(const Scenario& s, int frame, int& subframes) {
  const Scene scene = build_scene(s);
  const FrameRenderer fr(s, scene);
  std::vector<double> img;
  subframes = fr.render_radiance(frame, 0, img).subframes;
  return std::vector<double>(img.begin(), img.begin() + 80);
}

double covered(const std::vector<double>& r) {
  double sum = 0;
  for (double v : r) sum += v / 255.0;
  return sum;
}

}  // namespace

TEST_GROUP(Exposure){};

TEST(Exposure, TimestampIsTheMiddleOfTheExposure) {
  // The white length in a row is linear in time while the edge moves, so its
  // exposure average equals the instantaneous value at mid-exposure.
  int n0 = 0, n1 = 0;
  const auto sharp = row(moving_edge(5.0, 0), 3, n0);
  const auto blurred = row(moving_edge(5.0, 1.0), 3, n1);
  CHECK_EQUAL(1, n0);
  CHECK(n1 > 1);
  DOUBLES_EQUAL(covered(sharp), covered(blurred), 1e-6);
}

TEST(Exposure, MovingEdgeIsSpreadOverItsTravel) {
  const Pinhole p = pinhole_from_fov(80, 4, 50, 40);
  const double speed = 5.0, exposure = 0.8, rate = 30;
  const double travel_px = p.fu * speed * exposure / rate / 2.0;  // image motion during exposure
  CHECK(travel_px > 4);
  int n = 0;
  const auto img = row(moving_edge(speed, exposure), 3, n);
  int n0 = 0;
  const auto sharp = row(moving_edge(speed, 0), 3, n0);
  // Edge position at mid-exposure (from the sharp image, exact).
  const double ue = covered(sharp) - 0.5;
  // Expected: the box-filtered step averaged over the travel (the scene moves
  // towards -u as the camera moves forward). The midpoint rule over n
  // sub-frames (step h px) errs by at most h^2 / (4 travel) of full scale.
  const double h = travel_px / n;
  const double tol = 255.0 * h * h / (4 * travel_px) + 1e-9;
  int ramp = 0;
  for (int c = 0; c < 80; ++c) {
    const int m = 20000;
    double expect = 0;
    for (int k = 0; k < m; ++k) {
      const double shift = travel_px * ((k + 0.5) / m - 0.5);  // edge at ue - shift
      expect += std::clamp(ue - shift - (c - 0.5), 0.0, 1.0) / m;
    }
    DOUBLES_EQUAL(255.0 * expect, img[static_cast<size_t>(c)], tol);
    if (img[static_cast<size_t>(c)] > 2 && img[static_cast<size_t>(c)] < 253) ++ramp;
  }
  CHECK(ramp >= static_cast<int>(travel_px) - 1);
}

TEST(Exposure, ZeroExposureIsOneInstant) {
  int n = 0;
  const auto img = row(moving_edge(5.0, 0), 5, n);
  int partial = 0;  // pixels strictly between black and white (beyond rounding)
  for (double v : img)
    if (v > 1e-9 && v < 255 - 1e-9) ++partial;
  CHECK(partial <= 1);
}

TEST(Exposure, FlickerIsTheTrueRippleSampledAtFrameTimes) {
  // 100 Hz ripple seen at 20.8333 fps aliases to |100 - 5 * 20.8333| = 4.17 Hz.
  Scenario s = empty_scenario(8, 6);
  s.background = 100;
  s.camera.rate_hz = 62.5 / 3;
  s.lighting.flicker_hz = 100;
  s.lighting.flicker_amplitude = 0.2;
  const Scene scene = build_scene(s);
  const FrameRenderer fr(s, scene);
  std::vector<double> img;
  for (int i = 0; i < 10; ++i) {
    fr.render_radiance(i, 0, img);
    const double t = fr.frame_time(i);
    const double alias = 100.0 * (1 + 0.2 * std::sin(2 * 3.14159265358979323846 * (100.0 - 5 * 62.5 / 3) * t));
    DOUBLES_EQUAL(alias, img[0], 1e-6);
  }
}

TEST(Exposure, DarkIntervalsAreBlack) {
  Scenario s = empty_scenario(8, 6);
  s.background = 100;
  s.lighting.dark.push_back({0.1, 0.2});
  const Scene scene = build_scene(s);
  const FrameRenderer fr(s, scene);
  std::vector<double> img;
  for (int i = 0; i < 20; ++i) {
    fr.render_radiance(i, 0, img);
    const double t = fr.frame_time(i);
    DOUBLES_EQUAL(t >= 0.1 && t < 0.2 ? 0.0 : 100.0, img[3], 1e-12);
  }
}
