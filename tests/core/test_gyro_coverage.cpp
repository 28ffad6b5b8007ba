// Every frame whose interval [previous frame, this frame] the gyro samples do
// not cover carries kStatusGyroGap, in both engines alike: a gyro that stops,
// starts late, has a few samples, is 1000 s away, has a hole, or is absent.
#include <CppUTest/TestHarness.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

#include "lumavel/core/gyro_integrator.hpp"
#include "lumavel/core/status.hpp"
#include "lumavel/host/engine.hpp"
#include "synthetic_rig.hpp"

using namespace lumavel;

namespace {

constexpr double kFps = 60;
constexpr double kGap = 0.05;  // EstimatorSettings' default gyro gap, s

struct Frame {
  double t, t_prev;  // this frame and the previous one, s
  uint16_t fixed, dbl;
};

// The frames of an 8 s run at 0.5 m/s, rendered once for every test.
struct Scene {
  test::SyntheticRig rig;
  std::vector<std::vector<uint8_t>> cam[2];
  Scene() {
    rig.noise = 1.0;
    for (int i = 0; i < 8 * kFps; ++i)
      for (int c = 0; c < 2; ++c) cam[c].push_back(rig.render(c, test::Pose2{0.5 * i / kFps, 0, 0}));
  }
};
// Built before the test runner starts, so that its leak check does not count it.
const Scene kScene;
const Scene& scene() { return kScene; }

// The run with the given gyro sample times (s), fed by the push contract
// (every sample up to the first one at or after the frame).
std::vector<Frame> drive(const std::vector<double>& gyro_times) {
  const Scene& sc = scene();
  auto s = sc.rig.settings();
  s.frame_period = 1 / kFps;
  auto fixed = host::make_engine(host::EngineKind::kFixed, s);
  auto dbl = host::make_engine(host::EngineKind::kFloat, s);
  size_t next = 0;
  std::vector<Frame> out;
  for (size_t i = 0; i < sc.cam[0].size(); ++i) {
    const double t = static_cast<double>(i) / kFps;
    const uint64_t tn = static_cast<uint64_t>(std::llround(t * 1e9));
    while (next < gyro_times.size() && (next == 0 || gyro_times[next - 1] < t)) {
      const uint64_t tg = static_cast<uint64_t>(std::llround(gyro_times[next] * 1e9));
      fixed->push_gyro(tg, 0.02);
      dbl->push_gyro(tg, 0.02);
      ++next;
    }
    const uint8_t *a = sc.cam[0][i].data(), *b = sc.cam[1][i].data();
    out.push_back({t, i == 0 ? t : static_cast<double>(i - 1) / kFps, fixed->step(tn, a, b).status, dbl->step(tn, a, b).status});
  }
  return out;
}

std::vector<double> samples(double from, double to, double period = 0.005) {
  std::vector<double> t;
  for (double x = from; x <= to + 1e-12; x += period) t.push_back(x);
  return t;
}

// Checks every frame: flagged where `uncovered` says the interval has a
// point farther than the gap from the stream's coverage, clean where the
// whole interval lies more than a gap inside it; frames within a gap of a
// boundary may go either way. Both engines must flag alike everywhere.
template <typename Uncovered, typename Inside>
void check(const std::vector<Frame>& frames, Uncovered uncovered, Inside inside, const char* what) {
  int flagged = 0, clean = 0;
  for (const Frame& f : frames) {
    CHECK_EQUAL(f.fixed & kStatusGyroGap, f.dbl & kStatusGyroGap);
    CHECK_EQUAL(f.fixed, f.dbl);
    const bool gap = (f.fixed & kStatusGyroGap) != 0;
    if (uncovered(f)) {
      if (!gap) std::printf("\n  %s: frame at %.4f s (interval from %.4f s) not flagged", what, f.t, f.t_prev);
      CHECK(gap);
      ++flagged;
    } else if (inside(f)) {
      if (gap) std::printf("\n  %s: frame at %.4f s (interval from %.4f s) flagged", what, f.t, f.t_prev);
      CHECK_FALSE(gap);
      ++clean;
    }
  }
  std::printf("\n  %s: %d frames required flagged, %d required clean", what, flagged, clean);
}

}  // namespace

TEST_GROUP(GyroCoverage){};

TEST(GyroCoverage, FullStreamFlagsNothing) {
  const auto f = drive(samples(0, 8.1));
  check(f, [](const Frame&) { return false; }, [](const Frame&) { return true; }, "full stream");
}

TEST(GyroCoverage, GyroStoppingAt3sFlagsEveryLaterFrame) {
  const auto f = drive(samples(0, 3));
  check(f, [](const Frame& x) { return x.t > 3 + kGap; }, [](const Frame& x) { return x.t < 3 - kGap; },
        "stops at 3 s");
}

TEST(GyroCoverage, GyroStartingAt5sFlagsEveryEarlierFrame) {
  const auto f = drive(samples(5, 8.1));
  check(f, [](const Frame& x) { return x.t_prev < 5 - kGap; }, [](const Frame& x) { return x.t_prev > 5 + kGap; },
        "starts at 5 s");
}

TEST(GyroCoverage, FiveSamplesCoverOnlyTheirNeighbourhood) {
  const auto f = drive({2.0, 2.005, 2.010, 2.015, 2.020});
  check(f, [](const Frame& x) { return x.t > 2.02 + kGap || x.t_prev < 2.0 - kGap; },
        [](const Frame&) { return false; }, "five samples");
}

TEST(GyroCoverage, TimestampsFarFromEveryFrameFlagEveryFrame) {
  for (double offset : {1000.0, -1000.0}) {
    const auto f = drive(offset > 0 ? samples(offset, offset + 8) : std::vector<double>{});
    check(f, [](const Frame&) { return true; }, [](const Frame&) { return false; }, offset > 0 ? "1000 s later" : "none");
  }
}

TEST(GyroCoverage, GyroBeforeEveryFrameFlagsEveryFrame) {
  // Samples 1000 s before the frames: a stream that ended long ago.
  GyroIntegrator g;
  for (int i = 0; i < 100; ++i) g.push(static_cast<uint64_t>(i) * 5000000, 1 << 20);
  const uint64_t t = 1000000000000ull;
  CHECK_FALSE(g.covers(t, t + 16666667, 50000000));
  CHECK(g.covers(400000000, 495000000, 50000000));
}

TEST(GyroCoverage, EveryFrameInsideAHoleIsFlaggedNotOnlyTheFirst) {
  std::vector<double> t = samples(0, 2);
  for (double x : samples(4, 8.1)) t.push_back(x);
  const auto f = drive(t);
  check(f, [](const Frame& x) { return x.t > 2 && x.t_prev < 4; },
        [](const Frame& x) { return x.t < 2 - kGap || x.t_prev > 4 + kGap; }, "hole 2..4 s");
}

TEST(GyroCoverage, IntegratorCoverageRules) {
  GyroIntegrator g;
  const uint64_t gap = 50000000, ms = 1000000;
  CHECK_FALSE(g.covers(0, 0, gap));  // no samples
  g.push(100 * ms, 0);
  CHECK(g.covers(100 * ms, 140 * ms, gap));     // within a gap of the only sample
  CHECK_FALSE(g.covers(40 * ms, 100 * ms, gap));  // the stream starts 60 ms into the interval
  CHECK_FALSE(g.covers(100 * ms, 160 * ms, gap)); // held 60 ms past the last sample
  g.push(105 * ms, 0);
  g.push(300 * ms, 0);                            // a 195 ms hole
  CHECK_FALSE(g.covers(110 * ms, 126 * ms, gap)); // inside the hole
  CHECK(g.covers(300 * ms, 310 * ms, gap));       // after it
  CHECK_FALSE(g.covers(500 * ms, 500 * ms, gap)); // long after the last sample
}
