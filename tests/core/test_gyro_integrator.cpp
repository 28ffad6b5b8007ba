#include <CppUTest/TestHarness.h>

#include <cmath>

#include "lumavel/core/gyro_integrator.hpp"

using namespace lumavel;

namespace {
RateQ24 rate(double r) { return static_cast<RateQ24>(std::lround(std::ldexp(r, 24))); }
double rad(int64_t a) { return std::ldexp(static_cast<double>(a), -28); }
}  // namespace

TEST_GROUP(GyroIntegrator){};

TEST(GyroIntegrator, ConstantRateIntegratesExactly) {
  GyroIntegrator g;
  for (int i = 0; i <= 200; ++i) g.push(static_cast<uint64_t>(i) * 5000000, rate(0.3));  // 200 Hz, 1 s
  DOUBLES_EQUAL(0.3, rad(g.angle_at(1000000000)), 1e-7);
  DOUBLES_EQUAL(0.15, rad(g.angle_at(500000000)), 1e-7);
  DOUBLES_EQUAL(0.303, rad(g.angle_at(1010000000)), 1e-7);  // held beyond the last sample
}

TEST(GyroIntegrator, RampIsExactBetweenAndAtSamples) {
  // rate = t: angle = t^2 / 2, exact for the trapezoid on a linear rate.
  GyroIntegrator g;
  for (int i = 0; i <= 100; ++i) g.push(static_cast<uint64_t>(i) * 10000000, rate(i * 0.01));
  DOUBLES_EQUAL(0.5, rad(g.angle_at(1000000000)), 1e-6);
  // Between the last two samples: t = 0.995 s.
  DOUBLES_EQUAL(0.995 * 0.995 / 2, rad(g.angle_at(995000000)), 1e-6);
}

TEST(GyroIntegrator, ReportsLongestSpacingAndIgnoresOutOfOrder) {
  GyroIntegrator g;
  g.push(0, rate(1));
  g.push(5000000, rate(1));
  g.push(100000000, rate(1));  // a 95 ms hole
  g.push(90000000, rate(50));  // out of order: ignored
  LONGS_EQUAL(95000000, g.take_max_spacing());
  LONGS_EQUAL(0, g.take_max_spacing());
  DOUBLES_EQUAL(0.1, rad(g.angle_at(100000000)), 1e-7);
}

TEST(GyroIntegrator, NoSamplesMeansNoRotation) {
  GyroIntegrator g;
  LONGS_EQUAL(0, g.angle_at(123456789));
  CHECK_FALSE(g.has_samples());
}
