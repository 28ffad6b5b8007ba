#include <CppUTest/TestHarness.h>

#include <cmath>

#include "lumavel/core/fixed.hpp"

using namespace lumavel;

TEST_GROUP(Fixed){};

TEST(Fixed, ShrRoundIsSymmetric) {
  LONGS_EQUAL(2, fx::shr_round(3, 1));    // 1.5 -> 2
  LONGS_EQUAL(-2, fx::shr_round(-3, 1));  // -1.5 -> -2
  LONGS_EQUAL(1, fx::shr_round(5, 2));    // 1.25 -> 1
  LONGS_EQUAL(-1, fx::shr_round(-5, 2));
}

TEST(Fixed, Sat32ClampsAndReports) {
  bool sat = false;
  LONGS_EQUAL(fx::kInt32Max, fx::sat32(int64_t{1} << 40, &sat));
  CHECK_TRUE(sat);
  sat = false;
  LONGS_EQUAL(fx::kInt32Min, fx::sat32(-(int64_t{1} << 40), &sat));
  CHECK_TRUE(sat);
  sat = false;
  LONGS_EQUAL(-7, fx::sat32(-7, &sat));
  CHECK_FALSE(sat);
}

TEST(Fixed, DivQMatchesRoundedQuotient) {
  const int64_t cases[][2] = {{1, 3}, {-1, 3}, {22, 7}, {-22, 7}, {1000000007, 33}, {5, -9},
                              {int64_t{1} << 50, (int64_t{1} << 50) + 12345}, {7, int64_t{1} << 58}};
  for (const auto& c : cases)
    for (int q : {0, 8, 16, 28, 30}) {
      const double want = std::ldexp(static_cast<double>(c[0]) / static_cast<double>(c[1]), q);
      if (std::fabs(want) >= 2147483647.0) continue;
      bool sat = false;
      const int32_t got = fx::div_q(c[0], c[1], q, &sat);
      CHECK_FALSE(sat);
      DOUBLES_EQUAL(want, got, 0.5 + std::fabs(want) * 1e-12);
    }
}

TEST(Fixed, DivQLargeAndNegativeScales) {
  // q beyond 31 moves the scale into the operands; q < 0 shifts num.
  DOUBLES_EQUAL(std::ldexp(3.0 / 1e12, 50), fx::div_q(3, 1000000000000, 50), 1.0);
  DOUBLES_EQUAL(std::ldexp(1e6 / 3, -4), fx::div_q(1000000, 3, -4), 1.0);
}

TEST(Fixed, DivQSaturatesAndHandlesZero) {
  bool sat = false;
  LONGS_EQUAL(fx::kInt32Max, fx::div_q(1, 0, 16, &sat));
  CHECK_TRUE(sat);
  sat = false;
  LONGS_EQUAL(fx::kInt32Min, fx::div_q(-(int64_t{1} << 40), 3, 16, &sat));
  CHECK_TRUE(sat);
  sat = false;
  LONGS_EQUAL(0, fx::div_q(0, 0, 16, &sat));
  CHECK_FALSE(sat);
}
