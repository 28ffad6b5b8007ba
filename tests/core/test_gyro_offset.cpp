// The gyro's zero-rate offset is learned at standstill: with a 2 deg/s offset
// and no calibration, V comes out right after a standstill of 2 s.
#include <CppUTest/TestHarness.h>

#include <cmath>
#include <cstdio>

#include "lumavel/core/status.hpp"
#include "lumavel/host/engine.hpp"
#include "synthetic_rig.hpp"

using namespace lumavel;

namespace {

struct Result {
  double learned = 0, worst_moving = 0, still_frames = 0;
  uint16_t last_status = 0;
};

// Standstill for `still_s`, then 0.6 m/s while turning gently; gyro with offset.
Result drive(host::EngineKind kind, double offset, double still_s, bool learning,
             const test::SyntheticRig& base = test::SyntheticRig{}) {
  test::SyntheticRig rig = base;
  rig.noise = 1.0;
  auto s = rig.settings();
  s.gyro_offset_learning = learning;
  auto eng = host::make_engine(kind, s);
  Result r;
  double x = 0, th = 0;
  const double fps = 60, total = still_s + 2;
  for (int i = 0; i < total * fps; ++i) {
    const double t = i / fps;
    // Motion of the interval (t - 1/fps, t]: pose, gyro and image agree.
    const bool moving = i > 0 && t - 1 / fps >= still_s;
    const double v = moving ? 0.6 : 0, omega = moving ? 0.05 : 0;
    x += v / fps;
    th += omega / fps;
    for (int g = 0; g < 4; ++g) {  // 240 Hz gyro
      const double tg = t - 1 / fps + (g + 1) / (4 * fps);
      if (tg >= 0) eng->push_gyro(static_cast<uint64_t>(std::llround(tg * 1e9)), omega + offset);
    }
    const test::Pose2 p{x, 0, th};
    const auto a = rig.render(0, p), b = rig.render(1, p);
    const host::EngineEstimate e = eng->step(static_cast<uint64_t>(std::llround(t * 1e9)), a.data(), b.data());
    if (e.status & kStatusStill) ++r.still_frames;
    if (t >= still_s + 0.5) r.worst_moving = std::fmax(r.worst_moving, std::fabs(e.v - v));
    r.learned = e.gyro_offset;
    r.last_status = e.status;
  }
  return r;
}

}  // namespace

TEST_GROUP(GyroOffset){};

TEST(GyroOffset, LearnedAtStandstillAndVIsRight) {
  const double offset = 2 * M_PI / 180;
  for (auto kind : {host::EngineKind::kFixed, host::EngineKind::kFloat}) {
    const Result with = drive(kind, offset, 2.0, true), without = drive(kind, offset, 2.0, false);
    std::printf("\n  %s: offset learned %.5f rad/s (true %.5f); worst |V error| moving: %.4f m/s learned, %.4f m/s not",
                host::engine_name(kind), with.learned, offset, with.worst_moving, without.worst_moving);
    DOUBLES_EQUAL(offset, with.learned, 0.02 * offset);
    CHECK(with.worst_moving < 0.6 * 0.02);       // within 2 % of V
    CHECK(without.worst_moving > 0.6 * 0.05);    // the offset matters without learning
    CHECK(with.still_frames > 60);  // flagged from 0.5 s into the 2 s standstill
    CHECK_FALSE(with.last_status & kStatusStill);  // moving: not still
  }
}

TEST(GyroOffset, MovingRigIsNeverStill) {
  const Result r = drive(host::EngineKind::kFixed, 0.01, 0.0, true);
  LONGS_EQUAL(0, static_cast<long>(r.still_frames));
  DOUBLES_EQUAL(0.0, r.learned, 1e-12);
}

// Stripes whose period is twice the baseline: each camera sees the other's
// profile inverted, so the stereo mean M does not move while the rig does;
// each camera's own change must still tell it (before: STILL on every frame
// after 0.5 s, and the gentle turn learned as the gyro's offset).
TEST(GyroOffset, StripesOfTwiceTheBaselineAreNotStandstill) {
  test::SyntheticRig rig;
  rig.wall = 0.8;
  rig.texture = [h = rig.baseline](double X, double) { return 128 + 90 * std::sin(2 * M_PI * X / (2 * h)); };
  for (auto kind : {host::EngineKind::kFixed, host::EngineKind::kFloat}) {
    const Result r = drive(kind, 0.0, 0.0, true, rig);
    std::printf("\n  %s: %g still frames of 120, offset learned %.5f rad/s (true 0)", host::engine_name(kind),
                r.still_frames, r.learned);
    LONGS_EQUAL(0, static_cast<long>(r.still_frames));
    DOUBLES_EQUAL(0.0, r.learned, 1e-12);
  }
}

#include "lumavel/core/gyro_offset.hpp"

TEST(GyroOffset, ADayOfFrameIntervalsAddsNoRounding) {
  // Learn 0.0175 rad/s from a still reference, then subtract it over a day
  // of 60 Hz intervals: the sum must stay on offset * time.
  GyroOffset g;
  StereoMeasurement m{};
  m.count = 1;
  m.diff[0] = 1 << 24;
  const RateQ24 rate = 293601;  // 0.0175 rad/s in Q24
  const auto angle = [&](uint64_t t) { return static_cast<int64_t>(rate) * static_cast<int64_t>(t) / 62500000; };
  for (uint64_t t = 0; t <= 1000000000; t += 16666667)
    g.update({&m, t, angle(t), true, 1 << 20, 1 << 15, 500000});
  CHECK(g.still());
  const RateQ24 learned = g.offset();
  int64_t sum = 0;
  const int64_t n = 24 * 3600 * 60;
  int64_t t_ns = 0;
  for (int64_t i = 0; i < n; ++i) {
    const int64_t dt = i % 3 == 2 ? 16666666 : 16666667;  // 60 Hz in whole nanoseconds
    sum += g.take_angle_over(dt);
    t_ns += dt;
  }
  const double expected = std::ldexp(static_cast<double>(learned), -24) * static_cast<double>(t_ns) * 1e-9;
  const double err = std::ldexp(static_cast<double>(sum), -28) - expected;
  std::printf("\n  offset %.7f rad/s over 24 h of 60 Hz intervals: summed angle - offset * time = %.2e rad",
              std::ldexp(static_cast<double>(learned), -24), err);
  CHECK(std::fabs(err) < 1e-8);
  // A 3 h gap in one piece does not overflow.
  DOUBLES_EQUAL(std::ldexp(static_cast<double>(learned), -24) * 10800,
                std::ldexp(static_cast<double>(g.take_angle_over(10800ll * 1000000000)), -28), 1e-8);
}
