// Integer elementary functions: CORDIC for angles, range-reduced Taylor for exp.
#include "lumavel/core/imath.hpp"

namespace lumavel::fx {
namespace {

// atan(2^-i) in Q3.28.
constexpr int32_t kAtanTable[] = {
    210828714, 124459457, 65760959, 33381290, 16755422, 8385879, 4193963, 2097109,
    1048571,   524287,    262144,   131072,   65536,    32768,    16384,   8192,
    4096,      2048,      1024,     512,      256,      128,      64,      32,
    16,        8,         4,        2,        1};
constexpr int kCordicSteps = sizeof(kAtanTable) / sizeof(kAtanTable[0]);
// prod 1/sqrt(1 + 2^-2i) in Q1.30.
constexpr int64_t kCordicGainInvQ30 = 652032874;
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
  return static_cast<AngleQ28>(z);
}

}  // namespace

AngleQ28 atan_q16(int32_t x_q16) { return cordic_vector(int64_t{1} << 16, x_q16); }

AngleQ28 atan2_i32(int32_t y, int32_t x) {
  if (x == 0 && y == 0) return 0;
  if (x > 0) return cordic_vector(x, y);
  if (x == 0) return y > 0 ? kPiQ28 / 2 : -(kPiQ28 / 2);
  // x < 0: rotate by pi.
  const AngleQ28 a = cordic_vector(-int64_t{x}, -int64_t{y});
  return y >= 0 ? a + kPiQ28 : a - kPiQ28;
}

void cos_sin_q30(AngleQ28 a, int32_t* c, int32_t* s) {
  int64_t z = wrap_pi(a);
  // Reduce to [-pi/2, pi/2]; cos changes sign, sin keeps it.
  int sign = 1;
  if (z > kPiQ28 / 2) {
    z = kPiQ28 - z;
    sign = -1;
  } else if (z < -(kPiQ28 / 2)) {
    z = -kPiQ28 - z;
    sign = -1;
  }
  int64_t x = kCordicGainInvQ30 << 24;  // Q54 for precision
  int64_t y = 0;
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
  if (c) *c = sat32(sign * shr_round(x, 24));
  if (s) *s = sat32(shr_round(y, 24));
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

uint32_t isqrt64(uint64_t v) {
  uint64_t r = 0;
  uint64_t bit = uint64_t{1} << 62;
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

AngleQ28 wrap_pi(int64_t a) {
  const int64_t two_pi = int64_t{2} * kPiQ28;
  a %= two_pi;
  if (a >= kPiQ28) a -= two_pi;
  if (a < -kPiQ28) a += two_pi;
  return static_cast<AngleQ28>(a);
}

}  // namespace lumavel::fx
