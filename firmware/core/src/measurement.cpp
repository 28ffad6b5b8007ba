#include "lumavel/core/measurement.hpp"

#include "lumavel/core/estimator_params.hpp"
#include "lumavel/core/imath.hpp"

namespace lumavel {
namespace {

// sum_u w[u] * c[u]: q31 weights times sums of at most 23 bits (Q8 with a
// band), 32 x 32 -> 64 products (|sum| < 2^31 * 2^23 * 160 < 2^62).
int64_t dot(const KernelTable& t, const ColumnProfile& p) {
#if defined(__ARM_ARCH_6M__)
  // No 32 x 32 -> 64 multiply (M0/M0+: a library call per column). Plain sums
  // are in [0, 2^15): w = hi 2^16 + lo, lo in [0, 2^16), gives two exact 32-bit
  // products, |hi s| < 2^30 and lo s < 2^31; the same sum, bit for bit.
  if (!p.q8) {
    int64_t acc_hi = 0, acc_lo = 0;
    for (uint16_t u = 0; u < p.width; ++u) {
      const int32_t s = p.sum[u];
      acc_hi += (t.w[u] >> 16) * s;
      acc_lo += static_cast<uint32_t>(static_cast<uint32_t>(t.w[u]) & 0xFFFFu) * static_cast<uint32_t>(s);
    }
    return acc_hi * 65536 + acc_lo;
  }
#endif
  int64_t acc = 0;
  for (uint16_t u = 0; u < p.width; ++u) acc += int64_t{t.w[u]} * p.sum[u];
  return acc;
}

int64_t dot(const KernelTable16& t, const ColumnProfile& p) {
  int64_t acc = 0;
#if defined(__ARM_ARCH_6M__)
  // No 32 x 32 -> 64 multiply (M0/M0+): plain 15-bit sums keep 32-bit products.
  if (!p.q8) {
    for (uint16_t u = 0; u < p.width; ++u) acc += t.w[u] * p.sum[u];
    return acc;
  }
#endif
  // 16-bit weights times sums of at most 23 bits: |sum| < 2^15 * 2^23 * 160 < 2^46.
  for (uint16_t u = 0; u < p.width; ++u) acc += int64_t{t.w[u]} * p.sum[u];
  return acc;
}

// sum_u w[u] * v[u] for the edge-row profile (|v| < 2^23, as a banded sum).
int64_t dot_values(const KernelTable& t, const int32_t* v, uint16_t width) {
  int64_t acc = 0;
  for (uint16_t u = 0; u < width; ++u) acc += int64_t{t.w[u]} * v[u];
  return acc;
}

// The rotation term's edge-row correction (measurement.hpp), 2^kEdgeScaleBits x per column:
// C = lean x E, |lean| <= 4 (Q24), |4 E| < 2^18: |C| < 2^24.3 (times 2^31 x 160 < 2^63).
constexpr int kEdgeScaleBits = 6;  // C is 2^6 x lean x E
void edge_correction(const ColumnProfile& p, const LeanQ24* lean, int32_t* c) {
  for (uint16_t u = 0; u < p.width && u < kBandColumns; ++u)
    c[u] = static_cast<int32_t>(fx::shr_round(int64_t{lean[u]} * p.edge4[u], fx::kLeanFrac + 2 - kEdgeScaleBits));
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
int bit_length(uint64_t v) { return 64 - __builtin_clzll(v); }

Reciprocal reciprocal(int64_t n) {  // n > 0
  // N_norm: n shifted to 31 bits (truncated, as halving it would).
  const int e = bit_length(static_cast<uint64_t>(n)) - 31;
  n = e >= 0 ? n >> e : n << -e;
  return {(int64_t{1} << 61) / n, e};
}

// round(x / N * 2^q), saturated to int32; relative error ~1e-9.
int32_t ratio(int64_t x, const Reciprocal& r, int q, bool* sat) {
  // x / 2^sx (truncated towards zero) in [-2^31, 2^31), sx the least that fits.
  int sx = 0;
  if (x >= (int64_t{1} << 31) || x < -(int64_t{1} << 31)) {
    const uint64_t a = x < 0 ? 0 - static_cast<uint64_t>(x) : static_cast<uint64_t>(x);
    sx = bit_length(a) - 31;
    if (x < 0 && (a >> (sx - 1)) == (uint64_t{1} << 31)) --sx;  // -2^31 fits
    x = x < 0 ? -static_cast<int64_t>(a >> sx) : static_cast<int64_t>(a >> sx);
  }
  // x * 2^sx * mant / 2^61 / 2^exp * 2^q
  const int shift = 61 + r.exp - sx - q;
  const int64_t p = x * r.mant;  // < 2^62
  if (shift <= 0) {
    if (shift < -30) return fx::sat32(p >= 0 ? (int64_t{1} << 40) : -(int64_t{1} << 40), sat);
    return fx::sat32(fx::sat32(p, sat) * (int64_t{1} << -shift), sat);
  }
  if (shift >= 63) return 0;
  return fx::sat32(fx::shr_round(p, shift), sat);
}

struct CameraOutputs {
  ValueQ28 f[kMaxKernels];
  SlopeQ20 r[kMaxKernels];
  CurvQ12 c[kMaxKernels];
  bool no_light;
  bool saturated;
};

// F_k = B_k / N (paper eq. 21 applied after the kernel: one division per
// kernel instead of one per pixel); dF/dtheta = (dB - F dN) / N.
// lean: the bank's column leans where the profile has its edge rows (the
// rotation term's correction: measurement.hpp), else nullptr.
void camera_outputs(const ColumnProfile& p, const CameraKernels& ck, uint8_t count, const LeanQ24* lean,
                    CameraOutputs& out) {
  out.no_light = false;
  out.saturated = false;
  const int64_t n = dot(ck.norm, p);
  if (n <= 0) {
    out.no_light = true;
    for (uint8_t k = 0; k < count; ++k) out.f[k] = out.r[k] = out.c[k] = 0;
    return;
  }
  const Reciprocal inv = reciprocal(n);
  bool sat = false;
  // value of table t = w * 2^-(31 + exp): a ratio of two dots carries 2^(exp_n - exp_t).
  int32_t c[kBandColumns];
  if (lean) edge_correction(p, lean, c);
  // A correction term: x 2^-kEdgeScaleBits, through each table's own B kernel.
  const auto corr = [&](const KernelTable& t) {
    return lean ? int64_t{ratio(dot_values(t, c, p.width), inv, fx::kSlopeFrac - kEdgeScaleBits + ck.norm.exp - t.exp, &sat)} : 0;
  };
  const SlopeQ20 dn_over_n = fx::sat32(
      int64_t{ratio(dot(ck.norm_d, p), inv, fx::kSlopeFrac + ck.norm.exp - ck.norm_d.exp, &sat)} + corr(ck.norm), &sat);
  for (uint8_t k = 0; k < count; ++k) {
    const ValueQ28 f = ratio(dot(ck.k[k], p), inv, fx::kValueFrac + ck.norm.exp - ck.k[k].exp, &sat);
    const SlopeQ20 db_over_n = fx::sat32(
        int64_t{ratio(dot(ck.d[k], p), inv, fx::kSlopeFrac + ck.norm.exp - ck.d[k].exp, &sat)} + corr(ck.k[k]), &sat);
    out.f[k] = f;
    // T is a 16-bit table: value = w * 2^-(15 + exp), a 2^16 larger step than a q31 table.
    out.c[k] = ratio(dot(ck.t[k], p), inv, fx::kCurvFrac + ck.norm.exp - ck.t[k].exp + 16, &sat);
    out.r[k] = fx::sat32(int64_t{db_over_n} - fx::shr_round(int64_t{f} * dn_over_n, fx::kValueFrac), &sat);
  }
  out.saturated = sat;
}

int32_t clamp30(int64_t v) {
  const int64_t lim = int64_t{1} << 30;
  return static_cast<int32_t>(v > lim ? lim : (v < -lim ? -lim : v));
}

// The band of (sigma w)^2 a Gaussian-derivative kernel passes, Q24.
constexpr int64_t kSigmaW2MinQ24 = fx::q_of(params::kSigmaW2Min, 24);
constexpr int64_t kSigmaW2MaxQ24 = fx::q_of(params::kSigmaW2Max, 24);
static_assert(kSigmaW2MinQ24 > 0 && kSigmaW2MaxQ24 < (int64_t{1} << 30), "the root below needs u in (0, 2^30)");

// Half the phase difference between the cameras of kernel k (see measurement.hpp).
// (sigma w)^2 is clamped to [kSigmaW2Min, kSigmaW2Max] (estimator_params.hpp):
// continuous, so that noise near w^2 = 0 cannot switch the correction.
AngleQ28 half_phase(const CameraOutputs& c0, const CameraOutputs& c1, ValueQ28 dc0, ValueQ28 dc1,
                    AngleQ28 sigma, uint8_t k) {
  const int64_t r0 = c0.r[k], r1 = c1.r[k];  // Q20
  const int64_t rr = fx::shr_round(r0 * r0 + r1 * r1, 8);                                  // Q32
  if (rr == 0) return 0;
  const int64_t cr = -(int64_t{c0.c[k]} * r0 + int64_t{c1.c[k]} * r1);                    // Q32
  int64_t u = kSigmaW2MinQ24;  // (sigma w)^2, Q24
  if (cr > 0) {
    bool sat = false;
    const int64_t w2 = fx::div_q(cr, rr, 8, &sat);                                          // Q8 rad^-2
    const int64_t s2 = fx::shr_round(int64_t{sigma} * sigma, 28);                            // Q28 rad^2
    u = sat ? kSigmaW2MaxQ24 : fx::shr_round(w2 * s2, 12);
    u = u < kSigmaW2MinQ24 ? kSigmaW2MinQ24 : (u > kSigmaW2MaxQ24 ? kSigmaW2MaxQ24 : u);
  }
  // 1/w = sigma / sqrt(u): u brought into [2^28, 2^30) by even shifts for a
  // 15-bit root, then one division (32-bit work except that division).
  int s2 = 0;
  while (u < (int64_t{1} << 28)) {
    u *= 4;
    ++s2;
  }
  const int64_t root = fx::isqrt32(static_cast<uint32_t>(u));  // sqrt(u) * 2^(12 + s2)
  const int64_t inv_w = fx::div_q(sigma, root, 8 + s2);           // Q24 rad
  const int64_t a0 = clamp30(int64_t{c0.f[k]} - dc0), a1 = clamp30(int64_t{c1.f[k]} - dc1);
  const int64_t b0 = clamp30(-fx::shr_round(r0 * inv_w, 16)), b1 = clamp30(-fx::shr_round(r1 * inv_w, 16));
  int64_t re = a1 * a0 + b1 * b0, im = b1 * a0 - a1 * b0;  // Q56, |.| < 2^61
  while (re >= (int64_t{1} << 31) || re < -(int64_t{1} << 31) || im >= (int64_t{1} << 31) || im < -(int64_t{1} << 31)) {
    re /= 2;
    im /= 2;
  }
  return fx::atan2_fast(static_cast<int32_t>(im), static_cast<int32_t>(re)) / 2;
}

}  // namespace

void stereo_measurement(const ColumnProfile& p0, const ColumnProfile& p1, const KernelBank& bank,
                        const PhotometricBalance* balance, StereoMeasurement& out) {
  CameraOutputs c0, c1;
  camera_outputs(p0, bank.cam[0], bank.count, bank.leaning && p0.edges ? bank.lean[0] : nullptr, c0);
  camera_outputs(p1, bank.cam[1], bank.count, bank.leaning && p1.edges ? bank.lean[1] : nullptr, c1);
  for (uint8_t k = 0; k < bank.count; ++k) {
    const ValueQ28 delta = balance && !c0.no_light && !c1.no_light ? balance->offset(k) : 0;
    out.balance[k] = delta;
    c1.f[k] = fx::sat32(int64_t{c1.f[k]} - delta);
  }
  out.count = bank.count;
  out.no_light = c0.no_light || c1.no_light;
  bool sat = c0.saturated || c1.saturated;
  for (uint8_t k = 0; k < bank.count; ++k) {
    out.mid[k] = static_cast<ValueQ28>(fx::shr_round(int64_t{c0.f[k]} + c1.f[k], 1));
    out.diff[k] = fx::sat32(int64_t{c1.f[k]} - c0.f[k], &sat);
    out.rot[k] = static_cast<SlopeQ20>(fx::shr_round(int64_t{c0.r[k]} + c1.r[k], 1));
    out.f[0][k] = c0.f[k];
    out.f[1][k] = c1.f[k];
    out.r[0][k] = c0.r[k];
    out.r[1][k] = c1.r[k];
  }
  out.saturated = sat;
  out.clipped = p0.clipped + p1.clipped;
  for (uint8_t k = 0; k < bank.count; ++k)
    out.half_phase[k] = out.no_light ? 0 : half_phase(c0, c1, bank.dc[0][k], bank.dc[1][k], bank.sigma[k], k);
}

}  // namespace lumavel
