#include "lumavel/units/fixed.hpp"

namespace lumavel::fx {

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
  // Keep rem * 2^q below 2^62: drop low bits of both operands (ratio kept).
  const int64_t limit = int64_t{1} << (62 - q);
  while (den >= limit) {
    den /= 2;
    num /= 2;
  }
  const int64_t one = int64_t{1} << q;
  const int64_t ip = num / den;
  const int64_t rem = num % den;  // same sign as num
  const int64_t bound = int64_t{1} << (31 - q);
  if (ip >= bound || ip <= -bound) {
    if (saturated) *saturated = true;
    return num > 0 ? kInt32Max : kInt32Min;
  }
  const int64_t half = den / 2;
  const int64_t frac = (rem * one + (rem >= 0 ? half : -half)) / den;
  return sat32(ip * one + frac, saturated);
}

}  // namespace lumavel::fx
