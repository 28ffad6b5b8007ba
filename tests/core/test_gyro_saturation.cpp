// A gyro sample beyond the firmware's rate format (|rate| >= 128 rad/s, up
// to 1e300) is clipped to RateQ24's range by both engines, flagged
// kStatusSaturated on every frame whose angle rests on it, and V is held
// over those intervals instead of reading the clipped rotation as motion.
#include <CppUTest/TestHarness.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "lumavel/core/status.hpp"
#include "lumavel/host/engine.hpp"
#include "synthetic_rig.hpp"

using namespace lumavel;

namespace {

struct Outcome {
  int saturated_frames = 0;
  double worst_v_error[2] = {0, 0};  // fixed, double; after 0.5 s
};

// 2 s at 0.5 m/s, 200 Hz gyro at 0.05 rad/s with one sample of `spike` at 1 s.
Outcome drive(double spike) {
  test::SyntheticRig rig;
  rig.noise = 1.0;
  auto s = rig.settings();
  s.frame_period = 1.0 / 60;
  auto fixed = host::make_engine(host::EngineKind::kFixed, s);
  auto dbl = host::make_engine(host::EngineKind::kFloat, s);
  Outcome out;
  int g = 0;
  double th = 0;
  for (int i = 0; i < 120; ++i) {
    const double t = i / 60.0;
    for (; g * 0.005 <= t + 0.005; ++g) {
      const uint64_t tg = static_cast<uint64_t>(g) * 5000000;
      const double rate = g == 200 ? spike : 0.05;
      fixed->push_gyro(tg, rate);
      dbl->push_gyro(tg, rate);
    }
    const test::Pose2 p{0.5 * t, 0, th};
    th += 0.05 / 60;
    const auto a = rig.render(0, p), b = rig.render(1, p);
    const uint64_t tn = static_cast<uint64_t>(std::llround(t * 1e9));
    const host::EngineEstimate ef = fixed->step(tn, a.data(), b.data());
    const host::EngineEstimate ed = dbl->step(tn, a.data(), b.data());
    CHECK_EQUAL(ef.status, ed.status);
    CHECK(std::isfinite(ed.v) && std::isfinite(ed.heading) && std::isfinite(ed.distance));
    const bool sat = (ef.status & kStatusSaturated) != 0;
    if (sat) ++out.saturated_frames;
    // The spike's trapezoids (0.995..1.005 s) lie in the intervals ending at 1.0 and 1.0167 s.
    if ((i == 60 || i == 61) && std::fabs(spike) >= 128) CHECK(sat);
    if (i < 59 || i > 62) CHECK_FALSE(sat);
    if (t >= 0.5) {
      out.worst_v_error[0] = std::fmax(out.worst_v_error[0], std::fabs(ef.v - 0.5));
      out.worst_v_error[1] = std::fmax(out.worst_v_error[1], std::fabs(ed.v - 0.5));
    }
  }
  std::printf("\n  spike %g rad/s: %d frames saturated; worst |V - 0.5| fixed %.4f, double %.4f m/s", spike,
              out.saturated_frames, out.worst_v_error[0], out.worst_v_error[1]);
  return out;
}

}  // namespace

TEST_GROUP(GyroSaturation){};

TEST(GyroSaturation, ARailedSampleIsClippedFlaggedAndVHeldInBothEngines) {
  for (double spike : {1e300, -1e300, 200.0, 128.0}) {
    const Outcome o = drive(spike);
    CHECK(o.saturated_frames >= 2);
    CHECK(o.worst_v_error[0] < 0.5 * 0.02);
    CHECK(o.worst_v_error[1] < 0.5 * 0.02);
  }
}

TEST(GyroSaturation, ARateInsideTheFormatIsNotSaturated) {
  const Outcome o = drive(30.0);  // inside RateQ24 (and the MPU-6050's 34.9 rad/s)
  LONGS_EQUAL(0, o.saturated_frames);
}
