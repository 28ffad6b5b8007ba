// The cheap_pair preset makes the two cameras differ by what
// host_sim/scenarios/README.md says: black level 10 vs 12, gain x1.20,
// corner fall-off 30 vs 36 %, measured on the rendered 8-bit images of a
// black, a uniform and a textured wall; the ideal preset keeps them equal,
// and tone_pair differs in the tone curve alone.
#include <CppUTest/TestHarness.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "lumavel/host/render/frame_renderer.hpp"
#include "lumavel/host/render/scenario_loader.hpp"
#include "lumavel/host/render/scene.hpp"
#include "render_test_support.hpp"

using namespace lumavel::host::render;
using namespace lumavel::host::render::test;

namespace {

constexpr int kW = 160, kH = 120;

Scenario wall(const PatternSpec& p, const std::string& preset) {
  Scenario s = empty_scenario(kW, kH, 0);
  s.duration_s = 0.1;
  s.seed = 17;
  s.planes.push_back(wall_at(2.0, -5, 5, -3, 3, p));
  Overrides o;
  o.camera_mismatch = preset;
  apply_overrides(s, o);
  return s;
}

std::vector<uint8_t> image(const Scenario& s, int cam) {
  const Scene scene = build_scene(s);
  const FrameRenderer fr(s, scene);
  std::vector<uint8_t> px;
  fr.render(0, cam, px);
  return px;
}

double radius(int x, int y) {
  const double dx = x - 0.5 * (kW - 1), dy = y - 0.5 * (kH - 1);
  return std::sqrt((dx * dx + dy * dy) / (0.25 * (kW * kW + kH * kH)));
}

struct Stats {
  double mean = 0, rms = 0;
};

// Mean and rms contrast of the pixels whose radius is in [r0, r1).
Stats ring(const std::vector<uint8_t>& px, double r0, double r1) {
  double s = 0, s2 = 0, n = 0;
  for (int y = 0; y < kH; ++y) {
    for (int x = 0; x < kW; ++x) {
      const double r = radius(x, y);
      if (r < r0 || r >= r1) continue;
      const double v = px[static_cast<size_t>(y * kW + x)];
      s += v;
      s2 += v * v;
      n += 1;
    }
  }
  Stats st;
  st.mean = s / n;
  st.rms = std::sqrt(std::max(0.0, s2 / n - st.mean * st.mean));
  return st;
}

}  // namespace

TEST_GROUP(CameraMismatch){};

TEST(CameraMismatch, BlackLevelsAre10And12) {
  const Scenario s = wall(uniform(0), "cheap_pair");
  DOUBLES_EQUAL(10.0, ring(image(s, 0), 0, 2).mean, 0.2);
  DOUBLES_EQUAL(12.0, ring(image(s, 1), 0, 2).mean, 0.2);
}

TEST(CameraMismatch, UniformWallGainAndCornerFallOff) {
  const Scenario s = wall(uniform(100), "cheap_pair");
  const auto a = image(s, 0), b = image(s, 1);
  const double centre0 = ring(a, 0, 0.1).mean - 10, centre1 = ring(b, 0, 0.1).mean - 12;
  DOUBLES_EQUAL(100.0, centre0, 1.0);
  DOUBLES_EQUAL(1.20, centre1 / centre0, 0.01);
  // The outermost pixels (r from 0.985 to 1) against the centre: 30 and 36 %.
  const double fall0 = 1 - (ring(a, 0.985, 2).mean - 10) / centre0;
  const double fall1 = 1 - (ring(b, 0.985, 2).mean - 12) / centre1;
  DOUBLES_EQUAL(0.30, fall0, 0.01);
  DOUBLES_EQUAL(0.36, fall1, 0.01);
  DOUBLES_EQUAL(1.20, fall1 / fall0, 0.05);
}

TEST(CameraMismatch, TexturedWallMeanAndContrast) {
  const PatternSpec checkers = checker(0.1, 40, 200);
  const Scenario mm = wall(checkers, "cheap_pair"), twins = wall(checkers, "ideal");
  // Near the centre vignetting is small: the contrast ratio is the gain ratio.
  const Stats a = ring(image(mm, 0), 0, 0.3), b = ring(image(mm, 1), 0, 0.3);
  DOUBLES_EQUAL(1.20, (b.mean - 12) / (a.mean - 10), 0.02);
  DOUBLES_EQUAL(1.20, b.rms / a.rms, 0.03);
  const Stats c = ring(image(twins, 0), 0, 0.3), d = ring(image(twins, 1), 0, 0.3);
  DOUBLES_EQUAL(1.0, d.mean / c.mean, 0.02);
  DOUBLES_EQUAL(1.0, d.rms / c.rms, 0.03);
}

// tone_pair: the same gain, black level and lens, cam1's tone curve gamma
// 1.05: a uniform wall at 100 reads 255 (100 / 255)^1.05 = 95.4 in cam1.
TEST(CameraMismatch, TonePairDiffersInTheToneCurveOnly) {
  const Scenario s = wall(uniform(100), "tone_pair");
  DOUBLES_EQUAL(100.0, ring(image(s, 0), 0, 2).mean, 0.5);
  DOUBLES_EQUAL(255.0 * std::pow(100.0 / 255.0, 1.05), ring(image(s, 1), 0, 2).mean, 0.5);
  const Scenario white = wall(uniform(255), "tone_pair");
  DOUBLES_EQUAL(255.0, ring(image(white, 1), 0, 2).mean, 0.5);
}
