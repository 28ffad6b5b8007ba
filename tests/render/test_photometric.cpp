// Per-camera photometric response: on a uniform wall the image is the
// documented gain / black level / vignetting profile; fixed patterns are the
// same in every frame, seeded, per camera and of the given sigma; the
// auto-exposure wanders smoothly and independently per camera; an ideal
// block leaves the bytes alone; bad keys are refused with FILE:LINE.
#include <CppUTest/TestHarness.h>
// after TestHarness.h, which it needs
#include <CppUTest/MemoryLeakWarningPlugin.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "lumavel/host/render/frame_renderer.hpp"
#include "lumavel/host/render/photometric_response.hpp"
#include "lumavel/host/render/scenario_loader.hpp"
#include "lumavel/host/render/scene.hpp"
#include "render_test_support.hpp"

using namespace lumavel::host::render;
using namespace lumavel::host::render::test;

namespace {

constexpr int kW = 80, kH = 60;

// A uniform wall of `level` filling the view of a rig at rest; no noise.
Scenario uniform_wall(double level) {
  Scenario s = empty_scenario(kW, kH, 0);
  s.duration_s = 0.2;
  s.planes.push_back(wall_at(2.0, -5, 5, -3, 3, uniform(level)));
  return s;
}

std::vector<uint8_t> frame(const Scenario& s, int i, int cam) {
  const Scene scene = build_scene(s);
  const FrameRenderer fr(s, scene);
  std::vector<uint8_t> px;
  fr.render(i, cam, px);
  return px;
}

// Normalised radius of pixel (x, y): 1 at the outer corner of the corner pixel.
double radius(int x, int y, int w, int h) {
  const double dx = x - 0.5 * (w - 1), dy = y - 0.5 * (h - 1);
  return std::sqrt((dx * dx + dy * dy) / (0.25 * (w * w + h * h)));
}

double mean(const std::vector<double>& v) {
  double s = 0;
  for (double x : v) s += x;
  return s / static_cast<double>(v.size());
}

double rms_about_mean(const std::vector<double>& v) {
  const double m = mean(v);
  double s = 0;
  for (double x : v) s += (x - m) * (x - m);
  return std::sqrt(s / static_cast<double>(v.size()));
}

// The response of one camera to a uniform radiance, before rounding.
std::vector<double> response_to(const PhotometricSpec& p, double level, uint64_t seed, int cam, int w, int h,
                                double t = 0) {
  const CameraResponse r(p, seed, cam, w, h, 0, 10);
  std::vector<double> img(static_cast<size_t>(w) * static_cast<size_t>(h), level);
  r.apply(t, img);
  return img;
}

std::string error_of(const std::string& text) {
  try {
    parse_scenario(text, "bad.yaml");
  } catch (const ScenarioError& e) {
    return e.what();
  }
  return "(accepted)";
}

const char* const kScenario =
    "duration_s: 1\n"                                       // 1
    "camera:\n"                                             // 2
    "  resolution: [40, 30]\n"                              // 3
    "  photometric:\n"                                      // 4
    "    preset: cheap_pair\n"                              // 5
    "    cam1:\n"                                           // 6
    "      gain: 1.1\n"                                     // 7
    "      vignetting: [-0.3, 0.05]\n"                      // 8
    "      auto_exposure: {sigma: 0.02, interval_s: 3}\n"   // 9
    "trajectory:\n"                                         // 10
    "  segments:\n"                                         // 11
    "    - {type: straight, duration_s: 1, speed: 0.5}\n";  // 12

std::string replace(std::string s, const std::string& from, const std::string& to) {
  s.replace(s.find(from), from.size(), to);
  return s;
}

}  // namespace

// yaml-cpp allocates statics on first use, which CppUTest's per-test leak
// check would report; leaks are checked by the AddressSanitizer build instead.
TEST_GROUP(Photometric) {
  void setup() override { MemoryLeakWarningPlugin::saveAndDisableNewDeleteOverloads(); }
  void teardown() override { MemoryLeakWarningPlugin::restoreNewDeleteOverloads(); }
};

TEST(Photometric, UniformWallShowsGainBlackLevelAndVignetting) {
  Scenario s = uniform_wall(100);
  PhotometricSpec& p = s.camera.photometric[0];
  p.gain = 1.3;
  p.black_level = 9;
  p.vignetting[0] = -0.3;
  p.vignetting[1] = 0.05;
  const auto px = frame(s, 0, 0);
  for (int y = 0; y < kH; ++y) {
    for (int x = 0; x < kW; ++x) {
      const double r2 = radius(x, y, kW, kH) * radius(x, y, kW, kH);
      const double expected = 1.3 * 100 * (1 - 0.3 * r2 + 0.05 * r2 * r2) + 9;
      DOUBLES_EQUAL(expected, px[static_cast<size_t>(y * kW + x)], 0.5 + 1e-6);
    }
  }
  // The profile by hand: 139 at the centre, 1.3 * 100 * 0.75 + 9 = 106.5 at r = 1.
  CHECK(px[static_cast<size_t>(30 * kW + 40)] >= 138 && px[static_cast<size_t>(30 * kW + 40)] <= 139);
  CHECK(px[0] >= 106 && px[0] <= 108);
  // cam1 is still ideal.
  for (uint8_t v : frame(s, 0, 1)) CHECK_EQUAL(100, v);
}

TEST(Photometric, GammaCurve) {
  Scenario s = uniform_wall(64);
  s.camera.photometric[1].gamma = 0.5;
  for (uint8_t v : frame(s, 0, 1)) CHECK_EQUAL(128, v);  // 255 sqrt(64 / 255) = 127.75
  for (uint8_t v : frame(s, 0, 0)) CHECK_EQUAL(64, v);
}

TEST(Photometric, FixedPatternIsTheSameInEveryFrameAndSeeded) {
  Scenario s = uniform_wall(120);
  for (auto& p : s.camera.photometric) {
    p.prnu = 0.02;
    p.dsnu = 2;
    p.column_gain = 0.01;
    p.column_offset = 1;
  }
  s.seed = 5;
  const auto a = frame(s, 0, 0);
  CHECK(a == frame(s, 7, 0));  // drawn once, not per frame
  CHECK(a != frame(s, 0, 1));  // each camera has its own
  Scenario other = s;
  other.seed = 6;
  CHECK(a != frame(other, 0, 0));  // and the seed draws it
  // With pixel noise, frames differ but the pattern stays: the mean of many
  // frames approaches the noise-free pattern.
  Scenario noisy = s;
  noisy.pixel_noise_sigma = 2;
  noisy.duration_s = 1;
  const Scene scene = build_scene(noisy);
  const FrameRenderer fr(noisy, scene);
  std::vector<double> sum(a.size(), 0.0);
  std::vector<uint8_t> px;
  constexpr int kFrames = 50;
  for (int i = 0; i < kFrames; ++i) {
    fr.render(i, 0, px);
    for (size_t k = 0; k < px.size(); ++k) sum[k] += px[k];
  }
  double err2 = 0;
  for (size_t k = 0; k < a.size(); ++k) err2 += std::pow(sum[k] / kFrames - a[k], 2);
  // Noise 2 / sqrt(50) = 0.28 plus the noise-free frame's own rounding (0.29).
  CHECK(std::sqrt(err2 / static_cast<double>(a.size())) < 0.5);
}

TEST(Photometric, FixedPatternsHaveTheirSigma) {
  constexpr int w = 640, h = 480;
  PhotometricSpec prnu;
  prnu.prnu = 0.02;
  auto img = response_to(prnu, 120, 3, 0, w, h);
  for (double& v : img) v = v / 120 - 1;
  DOUBLES_EQUAL(0.02, rms_about_mean(img), 0.02 * 0.01);
  DOUBLES_EQUAL(0.0, mean(img), 5 * 0.02 / std::sqrt(w * h));

  PhotometricSpec dsnu;
  dsnu.dsnu = 3;
  img = response_to(dsnu, 120, 3, 0, w, h);
  DOUBLES_EQUAL(3.0, rms_about_mean(img), 3 * 0.01);

  // Column patterns: constant down each column, sigma across columns.
  PhotometricSpec col;
  col.column_gain = 0.01;
  col.column_offset = 1;
  img = response_to(col, 100, 3, 0, w, h);
  std::vector<double> first_row(img.begin(), img.begin() + w);
  for (int y = 1; y < h; ++y)
    for (int x = 0; x < w; ++x) CHECK_EQUAL(first_row[static_cast<size_t>(x)], img[static_cast<size_t>(y * w + x)]);
  // 100 * 0.01 and 1 gray level, independent: sqrt(2) gray levels; 640 columns
  // estimate it to 3 % (1 sigma).
  DOUBLES_EQUAL(std::sqrt(2.0), rms_about_mean(first_row), 0.15 * std::sqrt(2.0));
}

TEST(Photometric, AutoExposureWandersSmoothlyAndPerCamera) {
  PhotometricSpec p;
  p.gain = 1.1;
  p.auto_exposure.sigma = 0.05;
  p.auto_exposure.interval_s = 2;
  const CameraResponse r0(p, 9, 0, 4, 3, 0, 4000), r1(p, 9, 1, 4, 3, 0, 4000), again(p, 9, 0, 4, 3, 0, 4000);
  // At the knots (every 2 s from t = -2) the log gain is sigma x a unit normal.
  std::vector<double> log_gain;
  double max_step = 0, differ = 0;
  for (int k = 1; k < 2000; ++k) {
    const double t = -2 + 2.0 * k;
    log_gain.push_back(std::log(r0.exposure_gain(t) / 1.1));
    DOUBLES_EQUAL(r0.exposure_gain(t), again.exposure_gain(t), 0);
    differ += std::fabs(r0.exposure_gain(t) - r1.exposure_gain(t));
    // One frame at 60 Hz changes the gain very little (smooth, not stepped).
    max_step = std::max(max_step, std::fabs(r0.exposure_gain(t + 0.7 + 1.0 / 60) / r0.exposure_gain(t + 0.7) - 1));
  }
  double ms = 0;
  for (double g : log_gain) ms += g * g;
  DOUBLES_EQUAL(0.05, std::sqrt(ms / static_cast<double>(log_gain.size())), 0.05 * 0.1);
  CHECK(max_step < 0.003);
  CHECK(differ / 2000 > 0.02);  // two free-running cameras differ
  // The image follows the exposure gain of its frame.
  Scenario s = uniform_wall(100);
  s.duration_s = 6;
  s.camera.photometric[0] = p;
  const Scene scene = build_scene(s);
  const FrameRenderer fr(s, scene);
  std::vector<uint8_t> px;
  for (int i : {0, 100, 250}) {
    fr.render(i, 0, px);
    DOUBLES_EQUAL(100 * fr.response(0).exposure_gain(fr.frame_time(i)), px[0], 0.5 + 1e-6);
  }
}

TEST(Photometric, IdealBlockChangesNoByte) {
  Scenario s = uniform_wall(0);
  s.planes[0] = wall_at(2.0, -5, 5, -3, 3, checker(0.1, 20, 230));
  s.pixel_noise_sigma = 2;
  const auto a0 = frame(s, 2, 0), a1 = frame(s, 2, 1);
  Scenario t = s;
  Overrides o;
  o.camera_mismatch = "ideal";
  apply_overrides(t, o);
  t.camera.photometric[1].gain = 1.0;  // written out, still the default
  CHECK(a0 == frame(t, 2, 0));
  CHECK(a1 == frame(t, 2, 1));
  o.camera_mismatch = "cheap_pair";
  apply_overrides(t, o);
  CHECK(a1 != frame(t, 2, 1));
}

TEST(Photometric, ScenarioKeysStartFromThePreset) {
  const Scenario s = parse_scenario(kScenario, "good.yaml");
  const PhotometricSpec& c0 = s.camera.photometric[0];
  const PhotometricSpec& c1 = s.camera.photometric[1];
  STRCMP_EQUAL("cheap_pair", s.camera.photometric_preset.c_str());
  DOUBLES_EQUAL(10, c0.black_level, 0);  // the preset's
  DOUBLES_EQUAL(12, c1.black_level, 0);
  DOUBLES_EQUAL(0.01, c1.prnu, 0);
  DOUBLES_EQUAL(1.1, c1.gain, 0);  // the keys given
  DOUBLES_EQUAL(-0.3, c1.vignetting[0], 0);
  DOUBLES_EQUAL(0.05, c1.vignetting[1], 0);
  DOUBLES_EQUAL(0.02, c1.auto_exposure.sigma, 0);
  DOUBLES_EQUAL(3, c1.auto_exposure.interval_s, 0);
  // --camera-mismatch replaces the whole block.
  Scenario t = s;
  Overrides o;
  o.camera_mismatch = "ideal";
  apply_overrides(t, o);
  CHECK(t.camera.photometric[0].ideal() && t.camera.photometric[1].ideal());
  o.camera_mismatch = "no_such_preset";
  try {
    apply_overrides(t, o);
    FAIL("accepted an unknown preset");
  } catch (const ScenarioError& e) {
    STRCMP_CONTAINS("no_such_preset", e.what());
    STRCMP_CONTAINS("cheap_pair", e.what());
  }
}

TEST(Photometric, BadKeysAndValuesAreRefusedWithFileAndLine) {
  std::string e = error_of(replace(kScenario, "      gain: 1.1", "      gian: 1.1"));
  STRCMP_CONTAINS("bad.yaml:7:", e.c_str());
  STRCMP_CONTAINS("unknown key 'gian' in 'cam1'", e.c_str());
  e = error_of(replace(kScenario, "    cam1:", "    cam2:"));
  STRCMP_CONTAINS("bad.yaml:6:", e.c_str());
  STRCMP_CONTAINS("'cam2'", e.c_str());
  e = error_of(replace(kScenario, "preset: cheap_pair", "preset: twins"));
  STRCMP_CONTAINS("bad.yaml:5:", e.c_str());
  STRCMP_CONTAINS("'twins' is not one of: ideal, cheap_pair", e.c_str());
  e = error_of(replace(kScenario, "gain: 1.1", "gain: 0"));
  STRCMP_CONTAINS("bad.yaml:7:", e.c_str());
  STRCMP_CONTAINS("'gain' = 0 is out of range", e.c_str());
  e = error_of(replace(kScenario, "gain: 1.1", "gain: bright"));
  STRCMP_CONTAINS("bad.yaml:7:", e.c_str());
  STRCMP_CONTAINS("'gain' must be a number", e.c_str());
  e = error_of(replace(kScenario, "gain: 1.1", "prnu: 0.5"));
  STRCMP_CONTAINS("bad.yaml:7:", e.c_str());
  STRCMP_CONTAINS("'prnu' = 0.5 is out of range [0, 0.2]", e.c_str());
  e = error_of(replace(kScenario, "[-0.3, 0.05]", "[-1.2, 0.1]"));  // 1 - 1.2 + 0.1 < 0.05 at the corner
  STRCMP_CONTAINS("bad.yaml:8:", e.c_str());
  STRCMP_CONTAINS("within [0.05, 2]", e.c_str());
  e = error_of(replace(kScenario, "[-0.3, 0.05]", "[-0.3]"));
  STRCMP_CONTAINS("bad.yaml:8:", e.c_str());
  STRCMP_CONTAINS("'vignetting' must be a list of 2 numbers", e.c_str());
  e = error_of(replace(kScenario, "interval_s: 3", "period_s: 3"));
  STRCMP_CONTAINS("bad.yaml:9:", e.c_str());
  STRCMP_CONTAINS("'period_s' in 'auto_exposure'", e.c_str());
  e = error_of(replace(kScenario, "sigma: 0.02", "sigma: -1"));
  STRCMP_CONTAINS("bad.yaml:9:", e.c_str());
  e = error_of(replace(kScenario, "    preset: cheap_pair\n", "    preset: [cheap_pair]\n"));
  STRCMP_CONTAINS("bad.yaml:5:", e.c_str());
  const std::string block = "  photometric:\n    preset: cheap_pair\n    cam1:\n      gain: 1.1\n"
                            "      vignetting: [-0.3, 0.05]\n      auto_exposure: {sigma: 0.02, interval_s: 3}\n";
  e = error_of(replace(kScenario, block, "  photometric: cheap_pair\n"));
  STRCMP_CONTAINS("bad.yaml:4:", e.c_str());
  STRCMP_CONTAINS("'photometric' must be a map", e.c_str());
}
