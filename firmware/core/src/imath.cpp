// Integer elementary functions: CORDIC for atan, range-reduced Taylor for exp.
#include "lumavel/core/imath.hpp"

namespace lumavel::fx {
namespace {

// atan(2^-i) in Q3.32: the angle accumulates 4 bits finer than its Q3.28
// result so that the table's rounding does not add up over the steps.
constexpr int64_t kAtanTable[] = {
    3373259426, 1991351318, 1052175346, 534100635, 268086748, 134174063, 67103403, 33553749,
    16777131,   8388597,    4194303,    2097152,   1048576,   524288,    262144,   131072,
    65536,      32768,      16384,      8192,      4096,      2048,      1024,     512,
    256,        128,        64,         32,        16,        8,         4,        2};
constexpr int kCordicSteps = sizeof(kAtanTable) / sizeof(kAtanTable[0]);

// The first kFastSteps entries rounded to Q28 for atan2_fast, at compile time
// (per call, the 64-bit rounding of each entry was 5 instructions a step).
constexpr int kFastSteps = 24;
struct AtanQ28 {
  int32_t v[kFastSteps];
};
constexpr AtanQ28 atan_q28() {
  AtanQ28 t{};
  for (int i = 0; i < kFastSteps; ++i) t.v[i] = static_cast<int32_t>((kAtanTable[i] + 8) >> 4);
  return t;
}
constexpr AtanQ28 kAtanQ28 = atan_q28();
// prod 1/sqrt(1 + 2^-2i) in Q1.30.
constexpr int64_t kLn2Q27 = 93032640;

// Vectoring CORDIC for x > 0: returns atan(y/x) in Q3.28.
AngleQ28 cordic_vector(int64_t x, int64_t y) {
  // Scale up for precision: keep |x|,|y| below 2^60 / 1.65 through the steps.
  int64_t m = (x > (y < 0 ? -y : y)) ? x : (y < 0 ? -y : y);
  while (m < (int64_t{1} << 56)) {
    x *= 2;
    y *= 2;
    m *= 2;
  }
  int64_t z = 0;
  for (int i = 0; i < kCordicSteps; ++i) {
    const int64_t xs = x / (int64_t{1} << i);
    const int64_t ys = y / (int64_t{1} << i);
    if (y > 0) {
      x += ys;
      y -= xs;
      z += kAtanTable[i];
    } else {
      x -= ys;
      y += xs;
      z -= kAtanTable[i];
    }
  }
  return static_cast<AngleQ28>(shr_round(z, 4));
}

// 1 / prod sqrt(1 + 2^-2i) over the 32 steps, Q2.60: rotation CORDIC
// starts from this x so that its gain leaves a unit vector.
constexpr int64_t kCordicInvGainQ60 = 700114967507363456;

}  // namespace

int32_t cos_q30(AngleQ28 a) {
  // Fold into [-pi/2, pi/2]: cos(a) = -cos(a -+ pi) outside it.
  int64_t z = a;
  int sign = 1;
  if (z > kPiQ28 / 2) {
    z -= kPiQ28;
    sign = -1;
  } else if (z < -(kPiQ28 / 2)) {
    z += kPiQ28;
    sign = -1;
  }
  z *= 16;  // Q3.32, the table's format
  int64_t x = kCordicInvGainQ60 / 4, y = 0;  // Q2.58: |x|, |y| stay below 2^59 under the steps
  for (int i = 0; i < kCordicSteps; ++i) {
    const int64_t xs = x / (int64_t{1} << i);
    const int64_t ys = y / (int64_t{1} << i);
    if (z >= 0) {
      x -= ys;
      y += xs;
      z -= kAtanTable[i];
    } else {
      x += ys;
      y -= xs;
      z += kAtanTable[i];
    }
  }
  return static_cast<int32_t>(sign * shr_round(x, 28));
}

AngleQ28 atan2_i32(int32_t y, int32_t x) {
  if (x == 0 && y == 0) return 0;
  if (x > 0) return cordic_vector(x, y);
  if (x == 0) return y > 0 ? kPiQ28 / 2 : -(kPiQ28 / 2);
  // x < 0: rotate by pi.
  const AngleQ28 a = cordic_vector(-int64_t{x}, -int64_t{y});
  return y >= 0 ? a + kPiQ28 : a - kPiQ28;
}

int32_t exp_neg_q27(int64_t x_q27) {
  if (x_q27 <= 0) return int32_t{1} << 30;
  if (x_q27 >= int64_t{22} << 27) return 0;  // e^-22 < 2^-31
  const int64_t k = x_q27 / kLn2Q27;
  const int64_t r = x_q27 - k * kLn2Q27;  // [0, ln 2)
  // e^-r = 1 - r(1 - r/2(1 - r/3(...))), Horner from the 13th term, Q1.30.
  const int64_t one = int64_t{1} << 30;
  int64_t p = one;
  for (int n = 13; n >= 1; --n) p = one - (r * p / n) / (int64_t{1} << 27);
  return static_cast<int32_t>(shr_round(p, static_cast<int>(k)));
}

AngleQ28 atan2_fast(int32_t y32, int32_t x32) {
  if (x32 == 0 && y32 == 0) return 0;
  // Quadrant to x > 0, then max(|x|, |y|) into [2^28, 2^29): no overflow
  // under the CORDIC gain (1.65), and 28 bits of the ratio whatever the scale.
  int64_t x = x32, y = y32, base = 0;
  if (x < 0) {
    base = y >= 0 ? kPiQ28 : -kPiQ28;
    x = -x;
    y = -y;
  }
  while (x >= (int64_t{1} << 29) || y >= (int64_t{1} << 29) || y <= -(int64_t{1} << 29)) {
    x /= 2;
    y /= 2;
  }
  while (x < (int64_t{1} << 28) && y < (int64_t{1} << 28) && y > -(int64_t{1} << 28)) {
    x *= 2;
    y *= 2;
  }
  int32_t xs = static_cast<int32_t>(x), ys = static_cast<int32_t>(y), z = 0;
  // Unrolled: each step's shift and angle become constants, and the loop's
  // count, compare and table load go (the same steps, in the same order).
#pragma GCC unroll 24
  for (int i = 0; i < kFastSteps; ++i) {
    const int32_t dx = xs >> i, dy = ys >> i;
    const int32_t a = kAtanQ28.v[i];
    if (ys > 0) {
      xs += dy;
      ys -= dx;
      z += a;
    } else {
      xs -= dy;
      ys += dx;
      z -= a;
    }
  }
  return static_cast<AngleQ28>(base + z);
}

// floor(sqrt(v)) by binary digits; the 32-bit instance avoids 64-bit
// arithmetic where the operand allows it (per frame on small cores).
template <typename T>
uint32_t isqrt_digits(T v) {
  T r = 0;
  T bit = T{1} << (sizeof(T) * 8 - 2);
  while (bit > v) bit >>= 2;
  while (bit != 0) {
    if (v >= r + bit) {
      v -= r + bit;
      r = (r >> 1) + bit;
    } else {
      r >>= 1;
    }
    bit >>= 2;
  }
  return static_cast<uint32_t>(r);
}

#if defined(__ARM_FEATURE_IDIV) || defined(__riscv_div)
// Where the core divides in hardware: Newton's iteration from above, from
// one step past 2^s >= sqrt(v) (AM-GM keeps it at or above floor(sqrt(v))),
// falls to floor(sqrt(v)) and stops there: the digits' result, in a handful
// of divisions instead of 16 digit steps (half_phase: one per kernel a frame).
uint32_t isqrt32(uint32_t v) {
  if (v < 2) return v;
  const int s = (33 - __builtin_clz(v)) / 2;  // ceil(bits / 2)
  uint32_t x = ((uint32_t{1} << s) + (v >> s)) / 2;
  for (;;) {
    const uint32_t y = (x + v / x) / 2;
    if (y >= x) return x;
    x = y;
  }
}
// Above 32 bits, the same iteration from (isqrt32(v / 4^k) + 1) 2^k >=
// sqrt(v) (v / 4^k below 2^32; sqrt(m + 1) <= isqrt(m) + 1), already within
// 2^-15 of the root: a step or two of 64 / 32-bit divisions instead of 32
// digit steps in 64-bit arithmetic.
uint32_t isqrt64(uint64_t v) {
  if ((v >> 32) == 0) return isqrt32(static_cast<uint32_t>(v));
  const int k = (64 - __builtin_clzll(v) - 31) / 2;
  uint64_t x = (uint64_t{isqrt32(static_cast<uint32_t>(v >> (2 * k)))} + 1) << k;
  for (;;) {
    const uint64_t y = (x + udiv_trunc(v, x)) / 2;
    if (y >= x) return static_cast<uint32_t>(x);
    x = y;
  }
}
#else
uint32_t isqrt32(uint32_t v) { return isqrt_digits(v); }
uint32_t isqrt64(uint64_t v) { return isqrt_digits(v); }
#endif

// 2 pi in Q28 is 1686629713 + 0.06525 LSB: whole turns are taken off with
// that fraction (Q32), so that the wrap stays exact however many turns there
// were (2 kPiQ28 is 0.93 LSB too large: 3.5e-9 rad gained per turn).
constexpr int64_t kTwoPiQ28Whole = 1686629713;
constexpr int64_t kTwoPiQ28FracQ32 = 280256794;

AngleQ28 wrap_pi(int64_t a) {
  int64_t k = div_trunc(a, kTwoPiQ28Whole);  // turns, within one of the answer
  auto rest = [a](int64_t turns) { return a - turns * kTwoPiQ28Whole - shr_round(turns * kTwoPiQ28FracQ32, 32); };
  int64_t r = rest(k);
  while (r >= kPiQ28) r = rest(++k);
  while (r < -kPiQ28) r = rest(--k);
  return static_cast<AngleQ28>(r);
}

}  // namespace lumavel::fx
