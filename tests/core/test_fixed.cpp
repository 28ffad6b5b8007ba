#include <CppUTest/TestHarness.h>

#include <cmath>
#include <string>

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

// The 64 / 32 division from 32-bit divisions (the M3/M4 and RV32IM path of
// div_q) against the built-in 64-bit one: the same quotient and remainder on
// edge values and on 2 million operands of every bit length (the QEMU images'
// reports, compared bit for bit with the host's, cover its use in div_q).
TEST(Fixed, Udivmod64By32IsTheBuiltInDivision) {
  const auto check = [](uint64_t n, uint32_t d) {
    uint32_t r = 0xDEADBEEFu;
    const uint64_t q = fx::udivmod64_32(n, d, &r);
    if (q != n / d || r != n % d) {
      FAIL_TEST(("udivmod64_32(" + std::to_string(n) + ", " + std::to_string(d) + ")").c_str());
    }
  };
  const uint64_t ns[] = {0, 1, 2, 0xFFFFu, 0x10000u, 0xFFFFFFFFu, 0x100000000u, 0xFFFFFFFFFFFFFFFFu,
                         0x8000000000000000u, 0x7FFFFFFFFFFFFFFFu, 0xFFFFFFFF00000000u, 0x00000000FFFF0000u};
  const uint32_t ds[] = {1, 2, 3, 0xFFFFu, 0x10000u, 0x10001u, 0x7FFFFFFFu, 0x80000000u, 0xFFFFFFFFu, 0xFFFF0001u};
  for (uint64_t n : ns)
    for (uint32_t d : ds) check(n, d);
  uint64_t x = 0x9E3779B97F4A7C15u;  // splitmix64
  const auto next = [&x] {
    uint64_t z = (x += 0x9E3779B97F4A7C15u);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9u;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBu;
    return z ^ (z >> 31);
  };
  for (int i = 0; i < 2000000; ++i) {
    const uint64_t a = next(), b = next();
    const uint64_t n = a >> (a & 63);                    // every length of numerator
    uint32_t d = static_cast<uint32_t>(b >> (32 + (b & 31)));  // and of denominator
    if (d == 0) d = 1;
    check(n, d);
    check(n, d | 0x80000000u);  // normalised already
    check((uint64_t{d} << 32) - 1 - (a & 0xFFFF), d);  // quotients near 2^32
  }
}

// div_q_short (a root below 2^16 as denominator, half_phase's 1/w) against
// div_q over its documented range: 0 < den < 2^16, 0 <= q <= 30, every int32
// numerator length and sign, and the edges.
TEST(Fixed, DivQShortIsDivQOnItsRange) {
  uint64_t x = 0x2545F4914F6CDD1Du;
  const auto next = [&x] {
    x ^= x << 13;
    x ^= x >> 7;
    x ^= x << 17;
    return x;
  };
  const int32_t edges[] = {0, 1, -1, fx::kInt32Max, fx::kInt32Min + 1, 1 << 20, -(1 << 20)};
  for (int32_t num : edges)
    for (uint32_t den : {1u, 2u, 3u, 16384u, 32767u, 65535u})
      for (int q = 0; q <= 30; ++q)
        LONGS_EQUAL(fx::div_q(num, den, q), fx::div_q_short(num, den, q));
  for (int i = 0; i < 200000; ++i) {
    const uint64_t a = next(), b = next();
    const int32_t num = static_cast<int32_t>(static_cast<uint32_t>(a) >> (a >> 59));
    const uint32_t den = 1 + static_cast<uint32_t>((b & 0xFFFFu) >> ((b >> 16) & 15)) % 65535u;
    const int q = static_cast<int>((b >> 24) % 31);
    if (fx::div_q(num, den, q) != fx::div_q_short(num, den, q))
      FAIL_TEST(("div_q_short(" + std::to_string(num) + ", " + std::to_string(den) + ", " + std::to_string(q) + ")").c_str());
  }
}
