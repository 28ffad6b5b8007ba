// Yaw between frame times from asynchronous gyro samples.
#include <cmath>
#include <stdexcept>

#include "lumavel/host/vo/gyro_yaw.hpp"
// CppUTest last: its leak-detector macros redefine new.
#include "CppUTest/TestHarness.h"

using lumavel::host::vo::GyroYaw;

TEST_GROUP(VoGyroYaw){};

TEST(VoGyroYaw, IntegratesALinearRateExactlyBetweenAnyTimes) {
  GyroYaw g;
  // rate = 0.5 + 2 t (t in s), samples every 5 ms from t = 0.
  for (int i = 0; i <= 200; ++i) g.push(static_cast<uint64_t>(i) * uint64_t{5000000}, 0.5 + 2 * i * 0.005);
  // Frames at 0.0123 s and 0.0290 s: integral = 0.5 dt + (t1^2 - t0^2).
  const GyroYaw::Interval a = g.between(12300000ull, 29000000ull);
  DOUBLES_EQUAL(0.5 * 0.0167 + (0.029 * 0.029 - 0.0123 * 0.0123), a.yaw, 1e-12);
  DOUBLES_EQUAL(0.005, a.max_spacing, 1e-12);
  const GyroYaw::Interval b = g.between(29000000ull, 45000000ull);  // continues after forgetting
  DOUBLES_EQUAL(0.5 * 0.016 + (0.045 * 0.045 - 0.029 * 0.029), b.yaw, 1e-12);
}

TEST(VoGyroYaw, ReportsHolesAndIgnoresRepeatedSamples) {
  GyroYaw g;
  g.push(0, 1.0);
  g.push(10000000ull, 1.0);
  g.push(10000000ull, 99.0);  // same time again: ignored
  g.push(5000000ull, 99.0);   // older: ignored
  g.push(110000000ull, 1.0);  // 100 ms hole
  const GyroYaw::Interval a = g.between(20000000ull, 40000000ull);
  DOUBLES_EQUAL(0.02, a.yaw, 1e-12);
  DOUBLES_EQUAL(0.1, a.max_spacing, 1e-12);
  CHECK_THROWS(std::invalid_argument, g.push(120000000ull, std::nan("")));
}

TEST(VoGyroYaw, NoSamplesMeansNoRotationAndAGap) {
  GyroYaw g;
  const GyroYaw::Interval a = g.between(0, 20000000ull);
  DOUBLES_EQUAL(0, a.yaw, 0);
  DOUBLES_EQUAL(0.02, a.max_spacing, 1e-12);
}
