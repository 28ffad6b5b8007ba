// HOST ONLY: the named fixed-point formats of fixed.hpp to and from SI values
// in double, in one place beside the formats, so that no host file writes its
// own 65536.0 or bare shift. The firmware computes no floats and never
// includes this header (the forbidden-symbol check of the images would fail).
//
// Every conversion is exact in the Q -> SI direction (a Q value times a power
// of two; int64 below 2^53). SI -> Q rounds half away from zero.
#pragma once
#include <cmath>
#include <cstdint>

#include "lumavel/units/fixed.hpp"

namespace lumavel::si {

// q / 2^frac.
inline double from_q(int64_t q, int frac) { return std::ldexp(static_cast<double>(q), -frac); }

// x 2^frac rounded half away from zero, saturated to int32 (NaN: the top).
inline int32_t to_q32_sat(double x, int frac) {
  const double q = std::round(std::ldexp(x, frac));
  if (!(q < 2147483647.0)) return fx::kInt32Max;
  if (q < -2147483648.0) return fx::kInt32Min;
  return static_cast<int32_t>(q);
}

// x 2^frac rounded half away from zero into int64; x must fit (llround).
inline int64_t to_q64(double x, int frac) { return std::llround(std::ldexp(x, frac)); }

// One named format of fixed.hpp: its storage, its fraction bits, and the
// conversions to and from its SI unit.
template <typename Int, int Frac>
struct Format {
  static constexpr int kFrac = Frac;
  static double to_si(Int q) { return from_q(q, Frac); }
  // Rounded half away from zero; a 32-bit format saturates (NaN: the top), a
  // 64-bit one must hold the value.
  static Int from_si(double x) {
    static_assert(sizeof(Int) == 4 || sizeof(Int) == 8, "from_si: 32- or 64-bit formats");
    if constexpr (sizeof(Int) == 4) return to_q32_sat(x, Frac);
    else return to_q64(x, Frac);
  }
};

using Speed = Format<SpeedQ16, fx::kSpeedFrac>;                 // m/s
using Distance = Format<DistQ32, fx::kDistFrac>;                // m
using Angle = Format<AngleQ28, fx::kAngleFrac>;                 // rad
using Rate = Format<RateQ24, fx::kRateFrac>;                    // rad/s
using Length = Format<LengthQ24, fx::kLengthFrac>;              // m
using Pixel = Format<PixelQ16, fx::kPixelFrac>;                 // px
using Value = Format<ValueQ28, fx::kValueFrac>;                 // kernel outputs, dimensionless
using Scale = Format<ScaleQ24, fx::kScaleFrac>;                 // dimensionless
using EdgeOffset = Format<EdgeOffsetQ15, fx::kEdgeOffsetFrac>;  // rad (to_si only)

}  // namespace lumavel::si
