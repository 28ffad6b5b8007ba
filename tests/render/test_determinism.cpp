// Determinism: the same seed gives the same bytes whatever the threading;
// another seed gives other noise; pixel noise has the given sigma.
#include <CppUTest/TestHarness.h>
// after TestHarness.h, which it needs
#include <CppUTest/MemoryLeakWarningPlugin.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <vector>

#include "lumavel/host/image_io.hpp"
#include "lumavel/host/render/frame_renderer.hpp"
#include "lumavel/host/render/recording_renderer.hpp"
#include "lumavel/host/render/scene.hpp"
#include "render_test_support.hpp"

using namespace lumavel::host;
using namespace lumavel::host::render;
using namespace lumavel::host::render::test;

namespace {

Scenario noisy_scene(uint64_t seed) {
  Scenario s = empty_scenario(160, 120, 0.5);
  s.seed = seed;
  s.duration_s = 0.2;
  s.pixel_noise_sigma = 3;
  s.imu.gyro_noise_density = 0.001;
  s.planes.push_back(wall_at(2.0, -5, 5, -3, 3, uniform(128)));
  return s;
}

std::vector<uint8_t> frame(const Scenario& s, int i, int cam) {
  const Scene scene = build_scene(s);
  const FrameRenderer fr(s, scene);
  std::vector<uint8_t> px;
  fr.render(i, cam, px);
  return px;
}

}  // namespace

// The recording library keeps function-local statics (csv column lists) that
// CppUTest's per-test leak check would report; leaks are checked by the
// AddressSanitizer build instead.
TEST_GROUP(Determinism) {
  void setup() override { MemoryLeakWarningPlugin::saveAndDisableNewDeleteOverloads(); }
  void teardown() override { MemoryLeakWarningPlugin::restoreNewDeleteOverloads(); }
};

TEST(Determinism, SameSeedSameBytesOtherSeedOtherNoise) {
  const auto a = frame(noisy_scene(42), 3, 1);
  const auto b = frame(noisy_scene(42), 3, 1);
  const auto c = frame(noisy_scene(43), 3, 1);
  CHECK(a == b);
  CHECK(a != c);
  CHECK(frame(noisy_scene(42), 3, 0) != a);  // cameras have their own noise
  CHECK(frame(noisy_scene(42), 4, 1) != a);  // and so do frames
}

TEST(Determinism, PixelNoiseHasTheGivenSigma) {
  const auto px = frame(noisy_scene(7), 0, 0);
  double sum = 0, sum2 = 0;
  for (uint8_t v : px) {
    sum += v - 128.0;
    sum2 += (v - 128.0) * (v - 128.0);
  }
  const double n = static_cast<double>(px.size());
  DOUBLES_EQUAL(0.0, sum / n, 5 * 3 / std::sqrt(n));
  // Rounding adds 1/12 to the variance.
  DOUBLES_EQUAL(std::sqrt(9 + 1.0 / 12), std::sqrt(sum2 / n), 5 * 3 / std::sqrt(2 * n));
}

TEST(Determinism, ThreadCountDoesNotChangeTheRecording) {
  const Scenario s = noisy_scene(9);
  const std::string d1 = temp_dir("det1"), d2 = temp_dir("det2");
  RenderOptions one;
  one.threads = 1;
  one.progress = false;
  RenderOptions two;
  two.threads = 2;
  two.progress = false;
  render_recording(s, d1, one);
  render_recording(s, d2, two);
  int compared = 0;
  for (const auto& e : std::filesystem::recursive_directory_iterator(d1 + "/mav0")) {
    if (!e.is_regular_file()) continue;
    const std::string rel = e.path().string().substr(d1.size());
    if (rel.find("sensor.yaml") != std::string::npos) continue;  // holds no render output
    CHECK_EQUAL(read_text(d1 + rel), read_text(d2 + rel));
    ++compared;
  }
  CHECK(compared > 20);
}
