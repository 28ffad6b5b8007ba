// A gyro value that leaves both neighbours and comes back within one sample
// is a read glitch: replaced by the neighbours' mean and said; turns,
// vibration and samples beside a hole are left as they are.
#include <cmath>
#include <vector>

#include "lumavel/host/gyro_glitch.hpp"
#include "recording_fixture.hpp"
// CppUTest last: its leak-detector macros redefine new.
#include "CppUTest/TestHarness.h"

using namespace lumavel::host;

namespace {

constexpr double kPeriod = 0.005;  // 200 Hz

// Samples 5 ms apart whose yaw rate (z) is z(i).
template <typename Z>
std::vector<ImuSample> samples(int n, Z z) {
  std::vector<ImuSample> s(static_cast<size_t>(n));
  for (int i = 0; i < n; ++i) {
    s[static_cast<size_t>(i)].t_ns = uint64_t{1000000000} + static_cast<uint64_t>(i) * uint64_t{5000000};
    s[static_cast<size_t>(i)].w[2] = z(i);
  }
  return s;
}

}  // namespace

TEST_GROUP(GyroGlitch){};

// 30 rad/s for one sample of a slow turn: replaced, counted, named.
TEST(GyroGlitch, AnOutAndBackSampleIsReplacedByItsNeighboursMean) {
  auto s = samples(60, [](int i) { return i == 30 ? 30.0 : 0.02 + 0.001 * i; });
  const GyroGlitches g = repair_gyro_glitches(s, kPeriod);
  LONGS_EQUAL(1, g.count);
  LONGS_EQUAL(30, g.first_index);
  LONGS_EQUAL(2, g.first_axis);
  DOUBLES_EQUAL(30.0, g.first_value, 0);
  DOUBLES_EQUAL((s[29].w[2] + s[31].w[2]) / 2, s[30].w[2], 1e-12);
  DOUBLES_EQUAL(0.05, s[30].w[2], 1e-12);
  STRCMP_CONTAINS("imu0/data.csv:32, w_RS_S_z 30 rad/s", format_gyro_glitches(g, "imu0/data.csv").c_str());
}

// A turn that starts within a sample (0 -> 3 rad/s) does not come back; a rig
// shaken at +-1.5 rad/s sample to sample has a scatter that a 2 rad/s sample
// does not stand out of; a quiet gyro's noise is far below the bound.
TEST(GyroGlitch, TurnsVibrationAndNoiseAreLeftAlone) {
  auto step = samples(60, [](int i) { return i < 30 ? 0.0 : 3.0; });
  const auto step_before = step;
  LONGS_EQUAL(0, repair_gyro_glitches(step, kPeriod).count);
  auto shaken = samples(60, [](int i) { return (i % 2 ? 1.5 : -1.5) + (i == 30 ? 2.0 : 0.0); });
  LONGS_EQUAL(0, repair_gyro_glitches(shaken, kPeriod).count);
  auto noisy = samples(200, [](int i) { return 0.02 * std::sin(i * 1.7) + 0.01 * std::cos(i * 5.3); });
  LONGS_EQUAL(0, repair_gyro_glitches(noisy, kPeriod).count);
  for (size_t i = 0; i < step.size(); ++i) DOUBLES_EQUAL(step_before[i].w[2], step[i].w[2], 0);
}

// Beside a gyro hole a sample has no neighbour on that side: not judged.
TEST(GyroGlitch, ASampleBesideAHoleIsNotJudged) {
  auto s = samples(60, [](int i) { return i == 30 ? 30.0 : 0.0; });
  for (size_t i = 31; i < s.size(); ++i) s[i].t_ns += uint64_t{100000000};  // 100 ms missing after sample 30
  LONGS_EQUAL(0, repair_gyro_glitches(s, kPeriod).count);
  DOUBLES_EQUAL(30.0, s[30].w[2], 0);
}

// Loaded from a recording: the sample is repaired before any engine sees it,
// and the recording says where.
TEST(GyroGlitch, ARecordingsGlitchIsRepairedWhenLoaded) {
  fixture::TempDir dir;
  const std::string rec = fixture::write_recording(dir.path() + "/rec");
  const std::string imu = rec + "/mav0/imu0/data.csv";
  fixture::set_field(imu, 40, 3, "30");
  const Recording r = load_recording(rec);
  LONGS_EQUAL(1, r.gyro_glitches);
  DOUBLES_EQUAL(r.imu_samples[37].w[2], r.imu_samples[38].w[2], 1e-12);
  STRCMP_CONTAINS("imu0/data.csv:40, w_RS_S_z 30 rad/s", r.gyro_glitch_text.c_str());
  const Recording clean = load_recording(fixture::write_recording(dir.path() + "/clean"));
  LONGS_EQUAL(0, clean.gyro_glitches);
  STRCMP_EQUAL("", clean.gyro_glitch_text.c_str());
}
