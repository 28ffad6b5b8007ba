// Frames that cannot show motion: black, flat with noise, a plain wall.
// The VO must not crash, must raise the status bits and hold V, and must
// recover when texture returns.
#include <cmath>
#include <memory>
#include <vector>

#include "lumavel/core/status.hpp"
#include "lumavel/host/recording.hpp"
#include "lumavel/host/render/recording_renderer.hpp"
#include "lumavel/host/render/scenario_loader.hpp"
#include "lumavel/host/run_recording.hpp"
#include "lumavel/host/vo_engine.hpp"
#include "recording_fixture.hpp"
// CppUTest last: its leak-detector macros redefine new.
#include "CppUTest/TestHarness.h"
#include "CppUTest/MemoryLeakWarningPlugin.h"

using namespace lumavel;
using namespace lumavel::host;

namespace {

constexpr int kW = 40, kH = 30;

// A 2-D texture moving left by 0.4 px per frame; cam1 sees it 1.5 px to
// the left (a left-looking rig with cam1 ahead: a point about 2 m away).
std::vector<uint8_t> textured(int frame, int cam) {
  std::vector<uint8_t> px(kW * kH);
  for (int v = 0; v < kH; ++v)
    for (int u = 0; u < kW; ++u) {
      const double x = u + 0.4 * frame + 1.5 * cam, y = v;
      px[static_cast<size_t>(v * kW + u)] = static_cast<uint8_t>(
          std::lround(128 + 45 * std::sin(0.7 * x) * std::cos(0.55 * y) + 35 * std::sin(0.31 * x + 0.83 * y + 1)));
    }
  return px;
}

// Flat gray with +-2 gray levels of deterministic noise.
std::vector<uint8_t> flat(int frame, int cam) {
  std::vector<uint8_t> px(kW * kH);
  uint32_t s = 12345u + static_cast<uint32_t>(frame * 2 + cam);
  for (uint8_t& p : px) {
    s = s * 1664525u + 1013904223u;
    p = static_cast<uint8_t>(126 + (s >> 29) % 5);
  }
  return px;
}

Recording rig() {
  Recording r;
  r.root = "/synthetic";
  r.cam[0] = fixture::left_camera(kW, kH, -0.04);
  r.cam[1] = fixture::left_camera(kW, kH, 0.04);
  for (CameraSensor& c : r.cam) c.distortion = {0, 0, 0, 0};
  r.frame_period_s = 0.01;
  return r;
}

render::Scenario shortened(const char* file, int w, int h, double duration) {
  render::Scenario s = render::load_scenario(std::string(LUMAVEL_SCENARIO_DIR) + "/" + file);
  render::Overrides o;
  o.width = w;
  o.height = h;
  o.duration_s = duration;
  render::apply_overrides(s, o);
  return s;
}

std::vector<TrackPoint> run_vo(const std::string& dir, int w, int h) {
  RunOptions o;
  o.engine = EngineKind::kVo;
  o.size = {w, h};
  return run_recording(load_recording(dir), o, nullptr).track;
}

}  // namespace

TEST_GROUP(VoNoTexture){};

TEST(VoNoTexture, HoldsVThroughBlackAndFlatFramesAndRecovers) {
  const Recording rec = rig();
  std::unique_ptr<Engine> vo = make_vo_engine(rec, kW, kH);
  uint64_t t = 1000000000ull;
  int frame = 0;
  auto step = [&](std::vector<uint8_t> (*make)(int, int)) {
    vo->push_gyro(t, 0.0);
    const std::vector<uint8_t> a = make(frame, 0), b = make(frame, 1);
    const EngineEstimate e = vo->step(t, a.data(), b.data());
    t += 10000000ull;
    ++frame;
    return e;
  };
  EngineEstimate e;
  for (int i = 0; i < 30; ++i) e = step(textured);
  CHECK_EQUAL(0, e.status & kStatusLowTexture);
  CHECK(e.v > 0.5);  // moving forward (about 1.8 m/s for this texture)
  const double held = e.v;
  for (int i = 0; i < 10; ++i) {
    std::vector<uint8_t> (*black)(int, int) = [](int, int) { return std::vector<uint8_t>(kW * kH, 0); };
    e = step(black);
    CHECK_EQUAL(kStatusNoLight | kStatusLowTexture, e.status & (kStatusNoLight | kStatusLowTexture));
    DOUBLES_EQUAL(held, e.v, 0);
  }
  for (int i = 0; i < 20; ++i) {
    e = step(flat);
    CHECK_EQUAL(kStatusLowTexture, e.status & (kStatusLowTexture | kStatusNoLight));
    DOUBLES_EQUAL(held, e.v, 0);
  }
  int flagged = 0;
  for (int i = 0; i < 20; ++i) flagged += (step(textured).status & kStatusLowTexture) != 0;
  CHECK(flagged <= 2);  // the first textured frame only re-detects
  DOUBLES_EQUAL(held, vo->step(t, textured(frame, 0).data(), textured(frame, 1).data()).v, 0.1 * held);
}

TEST(VoNoTexture, NeverStartsOnBlackOrFlatFrames) {
  const Recording rec = rig();
  std::unique_ptr<Engine> vo = make_vo_engine(rec, kW, kH);
  const std::vector<uint8_t> black(kW * kH, 0), white(kW * kH, 255);
  for (int i = 0; i < 10; ++i) {
    const uint64_t t = 1000000000ull + static_cast<uint64_t>(i) * uint64_t{10000000};
    const EngineEstimate e = i % 2 ? vo->step(t, black.data(), black.data()) : vo->step(t, white.data(), white.data());
    CHECK(e.status & kStatusLowTexture);
    DOUBLES_EQUAL(0, e.v, 0);
  }
}

// One image on both cameras (a driver fault), exactly or within a gray level
// of noise: no stereo, so no scale; V must be held and flagged, not computed
// from points triangulated at infinity (it read 2e17 m/s, then 650 m/s).
TEST(VoNoTexture, OneImageOnBothCamerasIsHeldNotTriangulated) {
  const Recording rec = rig();
  std::unique_ptr<Engine> vo = make_vo_engine(rec, kW, kH);
  uint64_t t = 1000000000ull;
  for (int frame = 0; frame < 20; ++frame, t += 10000000ull) {
    vo->push_gyro(t, 0.0);
    const std::vector<uint8_t> a = textured(frame, 0);
    const EngineEstimate e = vo->step(t, a.data(), a.data());
    CHECK_EQUAL(kStatusNoStereo | kStatusLowTexture, e.status & (kStatusNoStereo | kStatusLowTexture));
    DOUBLES_EQUAL(0, e.v, 0);
  }
  uint32_t s = 7;
  for (int frame = 20; frame < 40; ++frame, t += 10000000ull) {
    vo->push_gyro(t, 0.0);
    const std::vector<uint8_t> a = textured(frame, 0);
    std::vector<uint8_t> b = a;
    for (uint8_t& p : b) {
      s = s * 1664525u + 1013904223u;
      p = static_cast<uint8_t>(p + (s >> 30) % 3 - 1);  // +-1 gray level
    }
    const EngineEstimate e = vo->step(t, a.data(), b.data());
    CHECK(e.status & kStatusLowTexture);
    CHECK(std::fabs(e.v) < 1e-9);
  }
}

// yaml-cpp (the scenario loader) allocates statics on first use: not leaks
// of the code under test (as in test_lens).
TEST_GROUP(VoNoTextureRendered) {
  fixture::TempDir dir;
  void setup() override { MemoryLeakWarningPlugin::saveAndDisableNewDeleteOverloads(); }
  void teardown() override { MemoryLeakWarningPlugin::restoreNewDeleteOverloads(); }
};

TEST(VoNoTextureRendered, PlainWallWithSensorNoiseIsLowTextureNotMotion) {
  // A plain wall 2 m away with 1 gray level of pixel noise, at its native
  // 160x120 (noise is strongest there) and binned to 40x30.
  render::RenderOptions ro;
  ro.threads = 2;
  ro.progress = false;
  const std::string rec = dir.path() + "/plain";
  render::render_recording(shortened("untextured_then_textured.yaml", 160, 120, 2.0), rec, ro);
  for (const auto& [w, h] : {std::pair{160, 120}, std::pair{40, 30}}) {
    const std::vector<TrackPoint> track = run_vo(rec, w, h);
    size_t low = 0;
    double worst = 0;
    for (const TrackPoint& p : track) {
      low += (p.status & kStatusLowTexture) != 0;
      worst = std::fmax(worst, std::fabs(p.v_est));
    }
    CHECK(low >= track.size() * 95 / 100);
    DOUBLES_EQUAL(0, worst, 0.05);
  }
}

TEST(VoNoTextureRendered, DarkFramesAreFlaggedAndHeld) {
  // The photo wall pass with the lights off during [3, 3.5) s (exposure
  // half a frame period).
  render::RenderOptions ro;
  ro.threads = 2;
  ro.progress = false;
  const std::string rec = dir.path() + "/dark";
  const render::Scenario s = shortened("dark_frames.yaml", 80, 60, 4.2);
  render::render_recording(s, rec, ro);
  const std::vector<TrackPoint> track = run_vo(rec, 40, 30);
  double v_before = 0;
  int dark = 0;
  double worst_after = 0;
  for (const TrackPoint& p : track) {
    const double t = static_cast<double>(static_cast<int64_t>(p.t_ns) - s.start_ns) * 1e-9;
    if (t < 3.0) v_before = p.v_est;
    if (t >= 3.0 && t < 3.5) {
      // Exposures straddling the switch are half lit: low texture; the
      // others are black.
      const bool black = t > 3.01 && t < 3.49;
      dark += black;
      CHECK(p.status & (black ? kStatusNoLight : kStatusLowTexture));
      DOUBLES_EQUAL(v_before, p.v_est, 0);
    }
    if (t >= 3.8) worst_after = std::fmax(worst_after, std::fabs(p.v_est - p.v_true));
  }
  CHECK(dark >= 25);
  DOUBLES_EQUAL(0, worst_after, 0.05);  // tracking again within 0.3 s of the light
}
