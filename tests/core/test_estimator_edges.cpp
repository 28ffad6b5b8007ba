// The estimator on awkward frames and timings: it flags, holds and recovers,
// never divides by zero or overflows.
#include <CppUTest/TestHarness.h>

#include <cmath>
#include <memory>
#include <vector>

#include "lumavel/core/estimator.hpp"
#include "lumavel/core/status.hpp"
#include "lumavel/host/engine.hpp"
#include "synthetic_rig.hpp"

using namespace lumavel;

namespace {

struct Harness {
  test::SyntheticRig rig;
  std::unique_ptr<Estimator> est = std::make_unique<Estimator>();
  explicit Harness(int w = 40, int h = 30) {
    rig.width = w;
    rig.height = h;
    auto s = rig.settings();
    s.frame_period = 1.0 / 60;
    CHECK(est->configure(host::to_fixed_config(s)) == ConfigError::kOk);
  }
  Estimate step_frames(uint64_t t, const std::vector<uint8_t>& a, const std::vector<uint8_t>& b) {
    est->push_gyro(t, 0);
    FramePair f{t, {a.data(), b.data()}, static_cast<uint16_t>(rig.width)};
    return est->step(f);
  }
  Estimate step_pose(uint64_t t, double x) {
    const test::Pose2 p{x, 0, 0};
    return step_frames(t, rig.render(0, p), rig.render(1, p));
  }
};

constexpr uint64_t kFrameNs = 16666667;

}  // namespace

TEST_GROUP(EstimatorEdges){};

TEST(EstimatorEdges, AllBlackFramesRaiseNoLightAndHoldV) {
  Harness h;
  Estimate e{};
  for (int i = 0; i < 30; ++i) e = h.step_pose(static_cast<uint64_t>(i) * kFrameNs, 0.5 * i / 60.0);
  const int32_t v = e.v;
  CHECK(std::fabs(std::ldexp(v, -16) - 0.5) < 0.01);
  std::vector<uint8_t> black(40 * 30, 0);
  for (int i = 30; i < 40; ++i) {
    e = h.step_frames(static_cast<uint64_t>(i) * kFrameNs, black, black);
    CHECK(e.status & kStatusNoLight);
    LONGS_EQUAL(v, e.v);
  }
}

// Lights off: the sensor's noise clipped at 0 (mean 0.6 DN, most pixels 0),
// different in each camera and frame. Divided by its own tiny N it read as
// texture and moved V by metres per second; it is no light (kNoLightMeanDn),
// V held, in both engines. A dim scene (the rig at 1/25 of its brightness,
// mean about 5 DN) is still measured.
TEST(EstimatorEdges, BlackFramesOfSensorNoiseAreNoLightAndHoldV) {
  for (auto kind : {host::EngineKind::kFixed, host::EngineKind::kFloat}) {
    test::SyntheticRig rig;
    rig.width = 40;
    rig.height = 30;
    auto s = rig.settings();
    s.frame_period = 1.0 / 60;
    auto eng = host::make_engine(kind, s);
    uint32_t seed = 12345;
    const auto noise_frame = [&] {
      std::vector<uint8_t> f(40 * 30);
      for (auto& px : f) {
        seed = seed * 1664525u + 1013904223u;
        const int v = static_cast<int>((seed >> 24) % 7) - 3;  // -3..3 DN about black
        px = static_cast<uint8_t>(v < 0 ? 0 : v);
      }
      return f;
    };
    const auto dim = [](std::vector<uint8_t> f) {
      for (auto& px : f) px = static_cast<uint8_t>(px / 25);
      return f;
    };
    host::EngineEstimate e{};
    int i = 0;
    for (; i < 30; ++i) {
      const uint64_t t = static_cast<uint64_t>(i) * kFrameNs;
      eng->push_gyro(t, 0);
      const test::Pose2 p{0.5 * i / 60.0, 0, 0};
      e = eng->step(t, rig.render(0, p).data(), rig.render(1, p).data());
    }
    const double v = e.v;
    DOUBLES_EQUAL(0.5, v, 0.01);
    for (; i < 50; ++i) {
      const uint64_t t = static_cast<uint64_t>(i) * kFrameNs;
      eng->push_gyro(t, 0);
      const auto a = noise_frame(), b = noise_frame();
      e = eng->step(t, a.data(), b.data());
      CHECK(e.status & kStatusNoLight);
      DOUBLES_EQUAL(v, e.v, 1e-12);
    }
    int dim_no_light = 0;
    for (; i < 80; ++i) {
      const uint64_t t = static_cast<uint64_t>(i) * kFrameNs;
      eng->push_gyro(t, 0);
      const test::Pose2 p{0.5 * i / 60.0, 0, 0};
      e = eng->step(t, dim(rig.render(0, p)).data(), dim(rig.render(1, p)).data());
      if (e.status & kStatusNoLight) ++dim_no_light;
    }
    LONGS_EQUAL(0, dim_no_light);
  }
}

TEST(EstimatorEdges, AllWhiteFramesAreSaturatedAndUntextured) {
  Harness h;
  std::vector<uint8_t> white(40 * 30, 255);
  Estimate e{};
  for (int i = 0; i < 5; ++i) e = h.step_frames(static_cast<uint64_t>(i) * kFrameNs, white, white);
  CHECK(e.status & kStatusSaturated);
  CHECK(e.status & kStatusLowTexture);
  LONGS_EQUAL(0, e.v);
}

TEST(EstimatorEdges, UniformGreyIsLowTextureAndVIsHeld) {
  Harness h;
  Estimate e{};
  for (int i = 0; i < 30; ++i) e = h.step_pose(static_cast<uint64_t>(i) * kFrameNs, 0.5 * i / 60.0);
  const int32_t v = e.v;
  std::vector<uint8_t> grey(40 * 30, 128);
  for (int i = 30; i < 60; ++i) {
    e = h.step_frames(static_cast<uint64_t>(i) * kFrameNs, grey, grey);
    CHECK(e.status & kStatusLowTexture);
    LONGS_EQUAL(v, e.v);
  }
}

TEST(EstimatorEdges, RecoversWithinHalfASecondWhenTextureReturns) {
  Harness h;
  std::vector<uint8_t> grey(40 * 30, 128);
  for (int i = 0; i < 30; ++i) h.step_frames(static_cast<uint64_t>(i) * kFrameNs, grey, grey);
  // Texture returns at 0.5 s with the rig moving at 0.8 m/s.
  double recovered_at = -1;
  for (int i = 30; i < 90; ++i) {
    const double t = i / 60.0;
    const Estimate e = h.step_pose(static_cast<uint64_t>(i) * kFrameNs, 0.8 * t);
    if (recovered_at < 0 && std::fabs(std::ldexp(e.v, -16) - 0.8) < 0.02 * 0.8) recovered_at = t - 0.5;
  }
  CHECK(recovered_at >= 0 && recovered_at < 0.5);
}

TEST(EstimatorEdges, FrameGapIsFlaggedAndLongGapRestarts) {
  Harness h;
  Estimate e{};
  int i = 0;
  for (; i < 20; ++i) e = h.step_pose(static_cast<uint64_t>(i) * kFrameNs, 0.5 * i / 60.0);
  ++i;  // one dropped frame
  e = h.step_pose(static_cast<uint64_t>(i) * kFrameNs, 0.5 * i / 60.0);
  CHECK(e.status & kStatusFrameGap);
  CHECK_FALSE(e.status & kStatusRestarted);
  CHECK(std::fabs(std::ldexp(e.v, -16) - 0.5) < 0.01);
  i += 60;  // a 1 s hole (> max_gap): restart, V held meanwhile
  e = h.step_pose(static_cast<uint64_t>(i) * kFrameNs, 0.5 * i / 60.0);
  CHECK(e.status & kStatusRestarted);
  ++i;
  e = h.step_pose(static_cast<uint64_t>(i) * kFrameNs, 0.5 * i / 60.0);
  CHECK(std::fabs(std::ldexp(e.v, -16) - 0.5) < 0.01);
}

TEST(EstimatorEdges, RepeatedTimestampRestartsInsteadOfDividingByZero) {
  Harness h;
  h.step_pose(0, 0);
  h.step_pose(kFrameNs, 0.01);
  const Estimate e = h.step_pose(kFrameNs, 0.01);
  CHECK(e.status & kStatusRestarted);
}

TEST(EstimatorEdges, GyroHoleIsFlagged) {
  Harness h;
  h.step_pose(0, 0);
  h.est->push_gyro(kFrameNs * 30, 0);  // 0.5 s without gyro samples
  const test::Pose2 p{0.01, 0, 0};
  auto a = h.rig.render(0, p), b = h.rig.render(1, p);
  FramePair f{kFrameNs * 30, {a.data(), b.data()}, 40};
  CHECK(h.est->step(f).status & kStatusGyroGap);
}

TEST(EstimatorEdges, MaxSizeFramesAndExtremeContrast) {
  // kMaxColumns x kMaxRows, half black and half white columns: no overflow,
  // a finite answer and the saturation flag.
  test::SyntheticRig rig;
  rig.width = kMaxColumns;
  rig.height = kMaxRows;
  auto s = rig.settings();
  auto est = std::make_unique<Estimator>();
  CHECK(est->configure(host::to_fixed_config(s)) == ConfigError::kOk);
  std::vector<uint8_t> img(static_cast<size_t>(kMaxColumns) * kMaxRows);
  for (int y = 0; y < kMaxRows; ++y)
    for (int x = 0; x < kMaxColumns; ++x) img[static_cast<size_t>(y * kMaxColumns + x)] = (x / 7) % 2 ? 255 : 0;
  Estimate e{};
  for (int i = 0; i < 4; ++i) {
    FramePair f{static_cast<uint64_t>(i) * kFrameNs, {img.data(), img.data()}, static_cast<uint16_t>(kMaxColumns)};
    e = est->step(f);
  }
  CHECK(e.status & kStatusSaturated);
  CHECK(std::fabs(std::ldexp(e.v, -16)) < 1e-3);  // identical frames: no motion
}

TEST(EstimatorEdges, LineScanFramesWork) {
  Harness h(128, 1);
  Estimate e{};
  for (int i = 0; i < 60; ++i) e = h.step_pose(static_cast<uint64_t>(i) * kFrameNs, 0.4 * i / 60.0);
  DOUBLES_EQUAL(0.4, std::ldexp(e.v, -16), 0.4 * 0.02);
}

TEST(EstimatorEdges, MisalignedRigConvergesWithinHalfASecond) {
  for (double deg : {-3.0, 1.6, 3.0}) {
    test::SyntheticRig rig;
    rig.misalignment = deg * M_PI / 180;
    auto s = rig.settings();
    auto eng = host::make_engine(host::EngineKind::kFixed, s);
    double worst_after = 0;
    for (int i = 0; i < 90; ++i) {
      const double t = i / 60.0;
      const test::Pose2 p{0.6 * t, 0, 0};
      eng->push_gyro(static_cast<uint64_t>(i) * kFrameNs, 0);
      const auto a = rig.render(0, p), b = rig.render(1, p);
      const host::EngineEstimate e = eng->step(static_cast<uint64_t>(i) * kFrameNs, a.data(), b.data());
      if (t >= 0.5) worst_after = std::fmax(worst_after, std::fabs(e.v - 0.6));
    }
    CHECK(worst_after < 0.6 * 0.03);
  }
}

TEST(EstimatorEdges, UnconfiguredEstimatorReturnsZeros) {
  Estimator est;
  uint8_t px[16] = {};
  FramePair f{1, {px, px}, 16};
  const Estimate e = est.step(f);
  LONGS_EQUAL(0, e.v);
}
