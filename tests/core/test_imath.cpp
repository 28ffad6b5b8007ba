// Error budgets of the integer elementary functions, against libm.
#include <CppUTest/TestHarness.h>

#include <cmath>
#include <cstdio>

#include "lumavel/core/imath.hpp"

using namespace lumavel;

namespace {
double rad(AngleQ28 a) { return std::ldexp(a, -28); }
}  // namespace

TEST_GROUP(IMath){};

TEST(IMath, AtanOfRatiosWithin5e9Rad) {
  double worst = 0;
  for (double x = -40; x <= 40; x += 0.0137) {
    const int32_t y = static_cast<int32_t>(std::lround(x * 65536));
    const double err = std::fabs(rad(fx::atan2_i32(y, 65536)) - std::atan(y / 65536.0));
    if (err > worst) worst = err;
  }
  std::printf("\n  atan worst error %.2e rad\n", worst);
  CHECK(worst < 5e-9);
}

TEST(IMath, Atan2AllQuadrants) {
  for (double a = -3.1; a < 3.14; a += 0.05) {
    const int32_t y = static_cast<int32_t>(std::lround(1e6 * std::sin(a)));
    const int32_t x = static_cast<int32_t>(std::lround(1e6 * std::cos(a)));
    DOUBLES_EQUAL(std::atan2(y, x), rad(fx::atan2_i32(y, x)), 5e-9);
  }
  LONGS_EQUAL(0, fx::atan2_i32(0, 0));
}

TEST(IMath, ExpNegRelativeError) {
  double worst = 0;
  for (double x = 0; x < 22; x += 0.0093) {
    const int64_t xq = std::llround(std::ldexp(x, 27));
    const double want = std::exp(-std::ldexp(static_cast<double>(xq), -27));
    const double got = std::ldexp(fx::exp_neg_q27(xq), -30);
    worst = std::fmax(worst, std::fabs(got - want));
  }
  std::printf("\n  exp(-x) worst absolute error %.2e\n", worst);
  CHECK(worst < 2e-9);
  LONGS_EQUAL(0, fx::exp_neg_q27(int64_t{30} << 27));
  LONGS_EQUAL(1 << 30, fx::exp_neg_q27(0));
}

TEST(IMath, Isqrt) {
  const uint64_t vals[] = {0, 1, 2, 3, 4, 15, 16, 17, 1000000, 0xFFFFFFFFull, 0xFFFFFFFFFFFFFFFFull};
  for (uint64_t v : vals) {
    const uint64_t r = fx::isqrt64(v);
    CHECK(r * r <= v);
    CHECK((r + 1) * (r + 1) > v || r == 0xFFFFFFFFull);
  }
}

TEST(IMath, WrapPi) {
  DOUBLES_EQUAL(-M_PI + 0.1, rad(fx::wrap_pi(std::llround(std::ldexp(M_PI + 0.1, 28)))), 1e-8);
  DOUBLES_EQUAL(0.5, rad(fx::wrap_pi(std::llround(std::ldexp(0.5 + 6 * M_PI, 28)))), 1e-7);
  // Exact after any number of turns (2 kPiQ28 would gain 3.5e-9 rad a turn:
  // 3.5e-3 rad after a million), both ways, and inside [-pi, pi) at the ends.
  for (long turns : {1000000L, -1000000L, 123456789L}) {
    const long double a = 0.25L + 2 * 3.14159265358979323846264338L * static_cast<long double>(turns);
    DOUBLES_EQUAL(0.25, rad(fx::wrap_pi(std::llround(std::ldexp(a, 28)))), 1e-8);
  }
  for (int64_t a = -3 * int64_t{fx::kPiQ28}; a < 3 * int64_t{fx::kPiQ28}; a += 9999991) {
    const AngleQ28 w = fx::wrap_pi(a);
    CHECK(w >= -fx::kPiQ28 && w < fx::kPiQ28);
  }
  CHECK(fx::wrap_pi(fx::kPiQ28) < 0);
  CHECK_EQUAL(-fx::kPiQ28 + 1, fx::wrap_pi(-fx::kPiQ28 + 1));
}

TEST(IMath, Atan2FastWithin2e7Rad) {
  double worst = 0;
  for (double a = -3.1; a < 3.14; a += 0.0037)
    for (double r : {3.0, 1e3, 1e6, 2e9}) {
      const int32_t y = static_cast<int32_t>(std::lround(r * std::sin(a)));
      const int32_t x = static_cast<int32_t>(std::lround(r * std::cos(a)));
      worst = std::fmax(worst, std::fabs(std::atan2(y, x) - rad(fx::atan2_fast(y, x))));
    }
  std::printf("\n  atan2_fast worst error %.2e rad\n", worst);
  CHECK(worst < 2e-7);
}

TEST(IMath, Isqrt32) {
  const uint32_t vals[] = {0, 1, 2, 3, 4, 15, 16, 17, 1000000, 0x3FFFFFFFu, 0xFFFFFFFFu};
  for (uint32_t v : vals) {
    const uint64_t r = fx::isqrt32(v);
    CHECK(r * r <= v);
    CHECK((r + 1) * (r + 1) > v);
  }
}

TEST(IMath, CosWithin3e9OverAFullTurn) {
  double worst = 0;
  for (double a = -M_PI + 1e-9; a < M_PI; a += 0.00731) {
    const AngleQ28 q = static_cast<AngleQ28>(std::lround(std::ldexp(a, 28)));
    const double err = std::fabs(std::ldexp(fx::cos_q30(q), -30) - std::cos(rad(q)));
    if (err > worst) worst = err;
  }
  std::printf("\n  cos worst error %.2e\n", worst);
  CHECK(worst < 3e-9);
}
