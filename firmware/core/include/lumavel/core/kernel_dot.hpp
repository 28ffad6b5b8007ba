// The kernel bank's dot products with a column profile, and the one
// division per camera that turns them into ratios (measurement.cpp, and the
// photometric match's Jacobian, photometric_match.cpp). Inline: they are the
// per-frame inner loops.
#pragma once
#include <cstdint>

#include "lumavel/core/column_profile.hpp"
#include "lumavel/core/fixed.hpp"
#include "lumavel/core/kernel_bank.hpp"

namespace lumavel::kdot {

// sum_u w[u] * s[u] over n columns, four columns a step: the same exact
// integer sum with a quarter of the loop's compare and branch (and loads the
// compiler can pair), where the products are 32 x 32 -> 64 (SMLAL, RV32 MUL/MULH).
template <typename W, typename S>
inline int64_t mac4(const W* w, const S* s, uint16_t n) {
  int64_t acc = 0;
  const W* const end4 = w + (n & ~3u);
  const W* const end = w + n;
  while (w != end4) {
    acc += int64_t{w[0]} * s[0];
    acc += int64_t{w[1]} * s[1];
    acc += int64_t{w[2]} * s[2];
    acc += int64_t{w[3]} * s[3];
    w += 4;
    s += 4;
  }
  while (w != end) acc += int64_t{*w++} * *s++;
  return acc;
}

// Two weight vectors against one s in one pass: each s[u] loaded once for
// both products, and one loop step for eight of them (the same two exact sums
// as two mac4 calls).
template <typename W, typename S>
inline void mac4x2(const W* w1, const W* w2, const S* s, uint16_t n, int64_t* acc1, int64_t* acc2) {
  int64_t a1 = 0, a2 = 0;
  const S* const end4 = s + (n & ~3u);
  const S* const end = s + n;
  while (s != end4) {
    a1 += int64_t{w1[0]} * s[0];
    a2 += int64_t{w2[0]} * s[0];
    a1 += int64_t{w1[1]} * s[1];
    a2 += int64_t{w2[1]} * s[1];
    a1 += int64_t{w1[2]} * s[2];
    a2 += int64_t{w2[2]} * s[2];
    a1 += int64_t{w1[3]} * s[3];
    a2 += int64_t{w2[3]} * s[3];
    w1 += 4;
    w2 += 4;
    s += 4;
  }
  while (s != end) {
    a1 += int64_t{*w1++} * *s;
    a2 += int64_t{*w2++} * *s++;
  }
  *acc1 = a1;
  *acc2 = a2;
}

#if defined(__ARM_ARCH_6M__)
// sum_u w[u] * (s[u] >> Shift) for sums (so shifted) in [0, 2^15), without a
// 32 x 32 -> 64 multiply (M0/M0+: a library call per column): w = hi 2^16 +
// lo, lo in [0, 2^16), gives two exact 32-bit products, |hi s| < 2^30 and
// lo s < 2^31; the same sum, bit for bit.
template <int Shift, typename S>
inline int64_t dot_halves(const int32_t* w, const S* s, uint16_t n) {
  int64_t acc_hi = 0, acc_lo = 0;
  for (uint16_t u = 0; u < n; ++u) {
    const int32_t v = s[u] >> Shift;
    acc_hi += (w[u] >> 16) * v;
    acc_lo += static_cast<uint32_t>(static_cast<uint32_t>(w[u]) & 0xFFFFu) * static_cast<uint32_t>(v);
  }
  return acc_hi * 65536 + acc_lo;
}
#endif

// sum_u w[u] * c[u]: q31 weights times sums of at most 23 bits (Q8 with a
// band), 32 x 32 -> 64 products (|sum| < 2^31 * 2^23 * 160 < 2^62). On
// M0/M0+, plain sums and plain sums times 256 (the match's mapping of twins,
// plain_x256) take dot_halves on the plain values.
inline int64_t dot(const KernelTable& t, const ColumnProfile& p) {
#if defined(__ARM_ARCH_6M__)
  if (!p.q8) return dot_halves<0>(t.w, p.sum, p.width);
  if (p.plain_x256) return dot_halves<8>(t.w, p.sum, p.width) * 256;
#endif
  return mac4(t.w, p.sum, p.width);
}

inline int64_t dot(const KernelTable16& t, const ColumnProfile& p) {
  int64_t acc = 0;
#if defined(__ARM_ARCH_6M__)
  // No 32 x 32 -> 64 multiply (M0/M0+): plain 15-bit sums keep 32-bit products
  // (sums that are plain ones times 256: on the plain ones, times 256 after).
  if (!p.q8) {
    for (uint16_t u = 0; u < p.width; ++u) acc += t.w[u] * p.sum[u];
    return acc;
  }
  if (p.plain_x256) {
    for (uint16_t u = 0; u < p.width; ++u) acc += t.w[u] * (p.sum[u] >> 8);
    return acc * 256;
  }
#endif
  // 16-bit weights times sums of at most 23 bits: |sum| < 2^15 * 2^23 * 160 < 2^46.
  return acc + mac4(t.w, p.sum, p.width);
}

// Paired products in one pass only where the registers hold two 64-bit sums
// beside the loop's own: not on ARMv6-M or RV32E, whose 64-bit products are
// library calls (paired, the M0+ frame took 1 900 instructions more; M0/M0+
// take the kernel dots on 16-bit halves besides).
#if defined(__ARM_ARCH_6M__) || defined(__riscv_32e) || defined(__riscv_e)
constexpr bool kPairedDots = false;
#else
constexpr bool kPairedDots = true;
#endif

// dot(a, p) and dot(b, p), in one pass where kPairedDots.
template <typename T>
inline void dot2(const T& a, const T& b, const ColumnProfile& p, int64_t* da, int64_t* db) {
  if (kPairedDots) {
    mac4x2(a.w, b.w, p.sum, p.width, da, db);
  } else {
    *da = dot(a, p);
    *db = dot(b, p);
  }
}

// sum_u w[u] * v[u] for the edge-row profile (|v| < 2^23, as a banded sum).
inline int64_t dot_values(const KernelTable& t, const int32_t* v, uint16_t width) { return mac4(t.w, v, width); }
inline void dot_values2(const KernelTable& a, const KernelTable& b, const int32_t* v, uint16_t width, int64_t* da,
                        int64_t* db) {
  if (kPairedDots) {
    mac4x2(a.w, b.w, v, width, da, db);
  } else {
    *da = mac4(a.w, v, width);
    *db = mac4(b.w, v, width);
  }
}

// One table against two value profiles.
inline void dot_values_shared(const KernelTable& t, const int32_t* v0, const int32_t* v1, uint16_t width, int64_t* d0,
                              int64_t* d1) {
  if (kPairedDots) {
    mac4x2(v0, v1, t.w, width, d0, d1);
  } else {
    *d0 = mac4(t.w, v0, width);
    *d1 = mac4(t.w, v1, width);
  }
}

// 1/N as a 31-bit mantissa and a power of two, so that each ratio X/N is
// one 32x32->64 multiply instead of a 64-bit division (no divider on M0, a
// slow library routine on M3).
struct Reciprocal {
  int64_t mant;  // 2^61 / N_norm, in (2^30, 2^31]
  int exp;       // N = N_norm * 2^exp, N_norm in [2^30, 2^31)
};

// Bits of v > 0 (CLZ on cores that have it, a short libgcc routine on M0+):
// the normalisations below in one step instead of a shift per bit.
inline int bit_length(uint64_t v) { return 64 - __builtin_clzll(v); }

inline Reciprocal reciprocal(int64_t n) {  // n > 0
  // N_norm: n shifted to 31 bits (truncated, as halving it would).
  const int e = bit_length(static_cast<uint64_t>(n)) - 31;
  n = e >= 0 ? n >> e : n << -e;
  return {(int64_t{1} << 61) / n, e};
}

// A camera's normaliser dot product N and its reciprocal, as its outputs
// were divided by them (inv.mant == 0: not taken, a frame without light).
struct Normaliser {
  int64_t n;
  Reciprocal inv;
};

// round(x / N * 2^q), saturated to int32; relative error ~1e-9.
inline int32_t ratio(int64_t x, const Reciprocal& r, int q, bool* sat) {
  // x / 2^sx (truncated towards zero) in [-2^31, 2^31), sx the least that fits.
  int sx = 0;
  if (x >= (int64_t{1} << 31) || x < -(int64_t{1} << 31)) {
    const uint64_t a = fx::magnitude(x);
    sx = bit_length(a) - 31;
    if (x < 0 && (a >> (sx - 1)) == (uint64_t{1} << 31)) --sx;  // -2^31 fits
    x = x < 0 ? -static_cast<int64_t>(a >> sx) : static_cast<int64_t>(a >> sx);
  }
  // x * 2^sx * mant / 2^61 / 2^exp * 2^q
  const int shift = 61 + r.exp - sx - q;
  // (x in int32, mant <= 2^31 in uint32: a 32 x 32 -> 64 product, not a 64-bit one)
  const int64_t p = int64_t{static_cast<int32_t>(x)} * int64_t{static_cast<uint32_t>(r.mant)};  // |p| <= 2^62
  if (shift <= 0) {
    if (shift < -30) return fx::sat32(p >= 0 ? (int64_t{1} << 40) : -(int64_t{1} << 40), sat);
    return fx::sat32(fx::sat32(p, sat) * (int64_t{1} << -shift), sat);
  }
  if (shift >= 63) return 0;
  if (shift >= 33) {
    // The rounding half 2^(shift-1) lies in the high word, so the low word
    // cannot carry into the result: |p|'s high word (< 2^30 + 1) rounded in
    // 32 bits, the same value as shr_round's 64-bit shift (< 2^30: no saturation).
    const uint64_t a = fx::magnitude(p);
    const uint32_t m = (static_cast<uint32_t>(a >> 32) + (uint32_t{1} << (shift - 33))) >> (shift - 32);
    return p < 0 ? -static_cast<int32_t>(m) : static_cast<int32_t>(m);
  }
  return fx::sat32(fx::shr_round(p, shift), sat);
}

}  // namespace lumavel::kdot
