// Named fixed-point formats of the firmware, with range, resolution and
// saturation. Every quantity crossing a module boundary uses one of these.
//
//   name        storage  format   range                 resolution        used for
//   q31_t       int32    Q0.31    [-1, 1)               4.66e-10          kernel tables (see kernel_bank.hpp)
//   AngleQ28    int32    Q3.28    [-8, 8) rad           3.73e-9 rad       angles: yaw, heading, gyro increments
//   RateQ24     int32    Q7.24    [-128, 128) rad/s     5.96e-8 rad/s     gyro rate (MPU-6050 max 34.9 rad/s)
//   LengthQ24   int32    Q7.24    [-128, 128) m         5.96e-8 m         baseline h (0.06 ppm of 8 cm)
//   SpeedQ16    int32    Q15.16   [-32768, 32768) m/s   1.53e-5 m/s       velocity V (report and state)
//   DistQ32     int64    Q31.32   +-2.1e9 m             2.3e-10 m         travelled distance s
//   ValueQ28    int32    Q3.28    [-8, 8)               3.73e-9           normalised kernel outputs F, S, dM
//   SlopeQ20    int32    Q11.20   [-2048, 2048) /rad    9.5e-7 /rad       angular derivative dF/dtheta
//   PixelQ16    int32    Q15.16   [-32768, 32768) px    1.53e-5 px        intrinsics fu, cu
//   CurvQ12     int32    Q19.12   [-524288, 524288)/rad^3 2.4e-4 /rad^3   d3F/dtheta3 (a correction term:
//                                                                         1e-4 relative is plenty)
//   FracQ16     int32    Q15.16   [0, 1] used           1.53e-5           fractions and ratios: the observer's
//                                                                         least-squares residual, weights,
//                                                                         relative precisions
//   ScaleQ24    int32    Q7.24    [0.5, 2] used         6e-8              the differential's scale against the
//                                                                         time of flight (velocity_fusion.hpp)
//   AccelQ16    int32    Q15.16   [-10, 10] m/s^2 used  1.53e-5 m/s^2     the fused velocity's rate of change
//   VarQ40      int64    Q23.40   [0, 2^23)             9.1e-13           variance of the scale (1e-8..1e-2)
//   TravelQ16Ns uint64   V (Q16 m/s) x ns, wrapping   1.5e-14 m         integral of the differential for the
//                                                                         time of flight: only differences
//                                                                         over its window are read (exact,
//                                                                         no division: travel_between)
//   EdgeOffsetQ15 int16  Q0.15    [-1, 1) rad           3.05e-5 rad       lens correction of a column edge,
//                                                                         added to the pinhole edge (config.hpp).
//                                                                         Rounding <= 1.5e-5 rad: 0.06 % of a
//                                                                         column at 40 columns / 60 deg, 0.2 %
//                                                                         at 128; held to the fixed-vs-float
//                                                                         V budget by test_fixed_vs_float
//   ElevationScaleQ14 uint16 Q1.14 (0, 2)              6.1e-5            a lens column's elevation scale,
//                                                                         f d(tan E)/d(row) over the common
//                                                                         band (cos(a_u) for a pinhole);
//                                                                         sets its band and table weight
//                                                                         (kernel_bank.hpp). Rounding 3e-5
//                                                                         relative, below the tables' own
//   LeanQ24     int32    Q7.24    [-4, 4] used          6e-8              a column's lean, -d ln(elevation
//                                                                         scale)/d(yaw): how fast its rows'
//                                                                         elevation extent shrinks sideways,
//                                                                         for the rotation term's edge-row
//                                                                         correction (measurement.hpp);
//                                                                         clamped to +-4 (76 deg off axis)
//
// Every conversion that can overflow saturates and reports it (see sat32).
#pragma once
#include <cstdint>

namespace lumavel {

using q31_t = int32_t;
using AngleQ28 = int32_t;
using RateQ24 = int32_t;
using LengthQ24 = int32_t;
using SpeedQ16 = int32_t;
using DistQ32 = int64_t;
using ValueQ28 = int32_t;
using SlopeQ20 = int32_t;
using PixelQ16 = int32_t;
using CurvQ12 = int32_t;
using EdgeOffsetQ15 = int16_t;
using ElevationScaleQ14 = uint16_t;
using LeanQ24 = int32_t;
using FracQ16 = int32_t;
using ScaleQ24 = int32_t;
using AccelQ16 = int32_t;
using VarQ40 = int64_t;
using TravelQ16Ns = uint64_t;

namespace fx {

constexpr int kAngleFrac = 28;
constexpr int kRateFrac = 24;
constexpr int kLengthFrac = 24;
constexpr int kSpeedFrac = 16;
constexpr int kDistFrac = 32;
constexpr int kValueFrac = 28;
constexpr int kSlopeFrac = 20;
constexpr int kPixelFrac = 16;
constexpr int kCurvFrac = 12;
constexpr int kEdgeOffsetFrac = 15;
constexpr int kElevationScaleFrac = 14;
constexpr int kLeanFrac = 24;
constexpr int kFracFrac = 16;
constexpr int kScaleFrac = 24;
constexpr int kAccelFrac = 16;
constexpr int kVarFrac = 40;

constexpr int32_t kInt32Max = 2147483647;
constexpr int32_t kInt32Min = -kInt32Max - 1;

// pi in Q3.28, rounded.
constexpr AngleQ28 kPiQ28 = 843314857;

// A gyro rate at either end of RateQ24 was clipped on the way in (the
// sensor's or the conversion's range): its true value is unknown.
constexpr bool rate_at_rail(RateQ24 r) { return r == kInt32Max || r == kInt32Min; }

// A constant in a Q format, built from its real value at compile time: use it
// only to initialise constexpr integers (the firmware computes no floats).
constexpr int64_t q_of(double v, int frac) {
  double s = v;
  for (int i = 0; i < frac; ++i) s *= 2;
  return static_cast<int64_t>(s >= 0 ? s + 0.5 : s - 0.5);
}

// Clamps a 64-bit value into int32; sets *saturated when it had to.
constexpr int32_t sat32(int64_t v, bool* saturated = nullptr) {
  if (v > kInt32Max) {
    if (saturated) *saturated = true;
    return kInt32Max;
  }
  if (v < kInt32Min) {
    if (saturated) *saturated = true;
    return kInt32Min;
  }
  return static_cast<int32_t>(v);
}

// Arithmetic shift right with round-half-away-from-zero (symmetric, so that
// positive and negative values carry no opposite biases).
constexpr int64_t shr_round(int64_t v, int s) {
  if (s <= 0) return v;
  const int64_t half = int64_t{1} << (s - 1);
  return v >= 0 ? (v + half) >> s : -((-v + half) >> s);
}

// n / d and n % d (*rem) for d in [1, 2^32), from 32-bit divisions only: the
// high word, then the remaining 64 / 32 bits in two 16-bit digits (Hacker's
// Delight, divlu). On cores with a 32-bit divider and none for 64 bits
// (Cortex-M3/M4, RV32IM) this replaces the generic 64-bit library division;
// the quotient and remainder are the same, bit for bit.
uint64_t udivmod64_32(uint64_t n, uint32_t d, uint32_t* rem);

// Where a 32-bit divider is in hardware and a 64-bit one is not, 64-bit
// divisions by a 32-bit denominator go through udivmod64_32.
#if defined(__ARM_FEATURE_IDIV) || (defined(__riscv) && defined(__riscv_div) && __riscv_xlen == 32)
constexpr bool kDivide64By32 = true;
#else
constexpr bool kDivide64By32 = false;
#endif

// a / b truncated toward zero and a % b (*r, if given) with the sign of a,
// exactly as the built-in operators (b > 0), through udivmod64_32 where that
// is the cheaper route and b < 2^32: for per-frame 64-bit divisions by
// constants (ns per s, the gyro's scale), which a 32-bit core otherwise
// sends to the generic library routine. Inline: elsewhere it is the operator.
inline int64_t div_trunc(int64_t a, int64_t b, int64_t* r = nullptr) {
  if (!kDivide64By32 || b > int64_t{0xFFFFFFFF} || a == INT64_MIN) {
    if (r) *r = a % b;
    return a / b;
  }
  uint32_t rm = 0;
  const uint64_t m = static_cast<uint64_t>(a < 0 ? -a : a);
  const int64_t q = static_cast<int64_t>(udivmod64_32(m, static_cast<uint32_t>(b), &rm));  // < 2^63
  if (r) *r = a < 0 ? -int64_t{rm} : int64_t{rm};
  return a < 0 ? -q : q;
}

// The same for unsigned operands.
inline uint64_t udiv_trunc(uint64_t a, uint64_t b, uint64_t* r = nullptr) {
  if (!kDivide64By32 || b > uint64_t{0xFFFFFFFF}) {
    if (r) *r = a % b;
    return a / b;
  }
  uint32_t rm = 0;
  const uint64_t q = udivmod64_32(a, static_cast<uint32_t>(b), &rm);
  if (r) *r = rm;
  return q;
}

// Rounded, saturated quotient num/den in Q(q) (0 <= q <= 62; beyond 31 the
// scale moves into num or den). A zero
// denominator saturates toward the sign of num and sets *saturated.
int32_t div_q(int64_t num, int64_t den, int q, bool* saturated = nullptr);

// div_q(num, den, q) (no flag) for 0 < den < 2^16 and 0 <= q <= 30, where
// |num| 2^q + den / 2 < 2^62 makes it div_q's one rounded division: here by
// long division in 16-bit digits, each one 32-bit division (a remainder
// below den < 2^16 keeps each partial dividend in 32 bits), not a 64-bit
// division and div_q's general case (the same integers).
inline int32_t div_q_short(int32_t num, uint32_t den, int q) {
  const bool negative = num < 0;
  const uint32_t mag = negative ? 0u - static_cast<uint32_t>(num) : static_cast<uint32_t>(num);
  const uint64_t n = (uint64_t{mag} << q) + den / 2;
  const uint32_t hi = static_cast<uint32_t>(n >> 32), lo = static_cast<uint32_t>(n);
  const uint32_t q2 = hi / den;
  uint32_t r = hi - q2 * den;
  const uint32_t mid = (r << 16) | (lo >> 16);
  const uint32_t q1 = mid / den;
  r = mid - q1 * den;
  const uint32_t q0 = ((r << 16) | (lo & 0xFFFFu)) / den;
  const uint64_t quot = (uint64_t{q2} << 32) + (uint64_t{q1} << 16) + q0;
  if (quot >= (uint64_t{1} << 31)) return negative ? kInt32Min : kInt32Max;
  return negative ? -static_cast<int32_t>(quot) : static_cast<int32_t>(quot);
}

// num / den in Q16 for 0 <= num <= den and den > 0 (a fraction), rounded,
// with one 32-bit division instead of div_q's 64-bit ones: both are shifted
// right until den < 2^16, which keeps 15-16 significant bits of den. Error
// <= 2^-15 of the result plus half a Q16 step (<= 4.6e-5 in all).
inline int32_t fraction_q16(int64_t num, int64_t den) {
  const int lz = __builtin_clzll(static_cast<uint64_t>(den));
  const int s = lz >= 48 ? 0 : 48 - lz;
  const uint32_t n = static_cast<uint32_t>(num >> s), d = static_cast<uint32_t>(den >> s);
  return static_cast<int32_t>(((n << 16) + d / 2) / d);
}

// v held to [lo, hi] (lo <= hi).
constexpr int64_t clamp64(int64_t v, int64_t lo, int64_t hi) { return v < lo ? lo : (v > hi ? hi : v); }

// |v| as unsigned: exact for every int64, INT64_MIN included (2^63).
constexpr uint64_t magnitude(int64_t v) { return v < 0 ? 0 - static_cast<uint64_t>(v) : static_cast<uint64_t>(v); }

// The travel from `since` to `now` (Q16 m/s x ns): exact while it is below
// 2^63, i.e. for any window of the time of flight.
constexpr int64_t travel_between(TravelQ16Ns now, TravelQ16Ns since) { return static_cast<int64_t>(now - since); }

}  // namespace fx
}  // namespace lumavel
