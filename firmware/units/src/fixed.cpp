#include "lumavel/units/fixed.hpp"

#include <cstdint>

namespace lumavel::fx {
uint64_t udivmod64_32(uint64_t n, uint32_t d, uint32_t* rem) {
  const uint32_t hi = static_cast<uint32_t>(n >> 32);
  if (hi == 0) {  // one 32-bit division
    const uint32_t q = static_cast<uint32_t>(n) / d;
    *rem = static_cast<uint32_t>(n) - q * d;
    return q;
  }
  const uint32_t q_hi = hi / d;
  const uint32_t r = hi - q_hi * d;  // < d: the rest's quotient fits 32 bits
  const uint32_t lo = static_cast<uint32_t>(n);
  // Normalise d to its top bit set; r:lo shifts along (r < d keeps it in 32 bits).
  const int s = __builtin_clz(d);
  const uint32_t dn = d << s;
  const uint32_t vn1 = dn >> 16, vn0 = dn & 0xFFFFu;
  const uint32_t un32 = s == 0 ? r : (r << s) | (lo >> (32 - s));
  const uint32_t un10 = lo << s;
  const uint32_t un1 = un10 >> 16, un0 = un10 & 0xFFFFu;
  constexpr uint32_t b = 0x10000u;
  // Each digit: estimate from the top halves, at most two corrections
  // (q <= 2^16 + 1 and vn0 < 2^16: q vn0 stays below 2^32).
  uint32_t q1 = un32 / vn1;
  uint32_t rhat = un32 - q1 * vn1;
  while (q1 >= b || q1 * vn0 > ((rhat << 16) | un1)) {
    --q1;
    rhat += vn1;
    if (rhat >= b) break;
  }
  const uint32_t un21 = (un32 << 16) + un1 - q1 * dn;  // modulo 2^32: the exact partial remainder
  uint32_t q0 = un21 / vn1;
  rhat = un21 - q0 * vn1;
  while (q0 >= b || q0 * vn0 > ((rhat << 16) | un0)) {
    --q0;
    rhat += vn1;
    if (rhat >= b) break;
  }
  *rem = ((un21 << 16) + un0 - q0 * dn) >> s;
  return (uint64_t{q_hi} << 32) | ((q1 << 16) + q0);
}

namespace {

// div_q's quotient where |num| 2^q < 2^62 (0 <= q <= 31, den > 0): R =
// floor((|num| 2^q + floor(den / 2)) / den) in one division is the two
// divisions' ip 2^q + frac below (ip 2^q den is a whole multiple of den).
// Saturated as there: R beyond int32 (toward either sign), and, for a
// negative num, R = 2^31 with |num| / den >= 2^(31 - q) (ip's bound; -2^31
// itself is returned unflagged where only the rounding reached it).
int32_t div_q_one_division(bool negative, uint64_t mag, int64_t den, int q, bool* saturated) {
  const uint64_t scaled = mag << q;
  const uint64_t r = udiv_trunc(scaled + static_cast<uint64_t>(den / 2), static_cast<uint64_t>(den));
  constexpr uint64_t kTwo31 = uint64_t{1} << 31;
  if (!negative) {
    if (r < kTwo31) return static_cast<int32_t>(r);
    if (saturated) *saturated = true;
    return kInt32Max;
  }
  if (r < kTwo31) return -static_cast<int32_t>(r);
  if (saturated && (r > kTwo31 || (scaled >> 31) >= static_cast<uint64_t>(den))) *saturated = true;
  return kInt32Min;
}

}  // namespace

int32_t div_q(int64_t num, int64_t den, int q, bool* saturated) {
  if (den == 0) {
    if (num == 0) return 0;
    if (saturated) *saturated = true;
    return num > 0 ? kInt32Max : kInt32Min;
  }
  if (den < 0) {
    den = -den;
    num = -num;
  }
  if (q < 0) {
    num = shr_round(num, -q);
    q = 0;
  }
  if (q > 31) {
    // Move the excess scale into the numerator while it fits, else out of den.
    while (q > 31 && num < (int64_t{1} << 61) && num > -(int64_t{1} << 61)) {
      num *= 2;
      --q;
    }
    while (q > 31) {
      den /= 2;
      --q;
      if (den == 0) {
        if (saturated) *saturated = true;
        return num > 0 ? kInt32Max : (num < 0 ? kInt32Min : 0);
      }
    }
  }
  // Keep rem * 2^q below 2^62: drop low bits of both operands (ratio kept),
  // all k halvings in one shift (was a loop, a halving a step: den > 0, and k
  // halvings of num toward zero are one division by 2^k toward zero).
  const int64_t limit = int64_t{1} << (62 - q);
  uint64_t mag = magnitude(num);
  if (den >= limit) {
    const int k = 64 - __builtin_clzll(static_cast<uint64_t>(den)) - (62 - q);
    den >>= k;
    mag >>= k;
    num = num < 0 ? -static_cast<int64_t>(mag) : static_cast<int64_t>(mag);
  }
  if (mag < (uint64_t{1} << (62 - q))) return div_q_one_division(num < 0, mag, den, q, saturated);
  const int64_t one = int64_t{1} << q;
  int64_t rem = 0;  // same sign as num
  const int64_t ip = div_trunc(num, den, &rem);
  const int64_t bound = int64_t{1} << (31 - q);
  if (ip >= bound || ip <= -bound) {
    if (saturated) *saturated = true;
    return num > 0 ? kInt32Max : kInt32Min;
  }
  const int64_t half = den / 2;
  const int64_t frac = div_trunc(rem * one + (rem >= 0 ? half : -half), den);
  return sat32(ip * one + frac, saturated);
}

}  // namespace lumavel::fx
