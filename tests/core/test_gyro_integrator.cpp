#include <CppUTest/TestHarness.h>

#include <cmath>
#include <cstdio>

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
}

namespace {

// A day of 200 Hz samples (timestamps jittered by up to +-0.5 ms): a
// 0.0175 rad/s offset, uniform noise of +-0.01 rad/s and slow turns to one side. Returns
// the integrator's angle minus the double-precision trapezoid of the same
// quantised rates (long double, compensated), in rad.
double day_long_integral_error() {
  GyroIntegrator g;
  uint64_t seed = 7;
  auto uniform = [&seed] {  // [-1, 1), a 64-bit LCG: the same on every platform
    seed = seed * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<double>(seed >> 11) / 4503599627370496.0 - 1.0;
  };
  long double sum = 0, carry = 0;  // Kahan
  uint64_t t_prev = 0;
  RateQ24 r_prev = 0;
  const uint64_t n = 24ull * 3600 * 200;
  for (uint64_t i = 0; i <= n; ++i) {
    const uint64_t t = i * 5000000 + 500000 + static_cast<uint64_t>(std::llround(uniform() * 500000));
    const double truth = 0.0175 + 0.15 * (1 + std::sin(static_cast<double>(i) * 1e-4));  // one way: a bias adds up
    const RateQ24 r = rate(truth + 0.01 * uniform());
    g.push(t, r);
    if (i > 0) {
      const long double dt = static_cast<long double>(t - t_prev) * 1e-9L;
      const long double inc = (std::ldexp(static_cast<long double>(r_prev), -24) +
                               std::ldexp(static_cast<long double>(r), -24)) / 2 * dt - carry;
      const long double next = sum + inc;
      carry = (next - sum) - inc;
      sum = next;
    }
    t_prev = t;
    r_prev = r;
  }
  return rad(g.angle_at(t_prev)) - static_cast<double>(sum);
}

}  // namespace

TEST(GyroIntegrator, ADayOfSamplesStaysOnTheDoubleIntegral) {
  const double err = day_long_integral_error();
  std::printf("\n  24 h at 200 Hz: integer - double integral = %.3e rad", err);
  CHECK(std::fabs(err) < 1e-7);
}
