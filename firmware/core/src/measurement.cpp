#include "lumavel/core/measurement.hpp"

namespace lumavel {
namespace {

// sum_u w[u] * c[u]: q31 weights times 15-bit sums, 64-bit accumulator
// (|sum| < 2^31 * 2^15 * 160 < 2^54).
int64_t dot(const KernelTable& t, const ColumnProfile& p) {
  int64_t acc = 0;
  for (uint16_t u = 0; u < p.width; ++u) acc += int64_t{t.w[u]} * p.sum[u];
  return acc;
}

// 1/N as a 31-bit mantissa and a power of two, so that each ratio X/N is
// one 32x32->64 multiply instead of a 64-bit division (no divider on M0, a
// slow library routine on M3).
struct Reciprocal {
  int64_t mant;  // 2^61 / N_norm, in (2^30, 2^31]
  int exp;       // N = N_norm * 2^exp, N_norm in [2^30, 2^31)
};

Reciprocal reciprocal(int64_t n) {  // n > 0
  int e = 0;
  while (n >= (int64_t{1} << 31)) {
    n /= 2;
    ++e;
  }
  while (n < (int64_t{1} << 30)) {
    n *= 2;
    --e;
  }
  return {(int64_t{1} << 61) / n, e};
}

// round(x / N * 2^q), saturated to int32; relative error ~1e-9.
int32_t ratio(int64_t x, const Reciprocal& r, int q, bool* sat) {
  int sx = 0;
  while (x >= (int64_t{1} << 31) || x < -(int64_t{1} << 31)) {
    x /= 2;
    ++sx;
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
void camera_outputs(const ColumnProfile& p, const CameraKernels& ck, uint8_t count,
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
  const SlopeQ20 dn_over_n = ratio(dot(ck.norm_d, p), inv, fx::kSlopeFrac + ck.norm.exp - ck.norm_d.exp, &sat);
  for (uint8_t k = 0; k < count; ++k) {
    const ValueQ28 f = ratio(dot(ck.k[k], p), inv, fx::kValueFrac + ck.norm.exp - ck.k[k].exp, &sat);
    const SlopeQ20 db_over_n = ratio(dot(ck.d[k], p), inv, fx::kSlopeFrac + ck.norm.exp - ck.d[k].exp, &sat);
    out.f[k] = f;
    out.c[k] = ratio(dot(ck.t[k], p), inv, fx::kCurvFrac + ck.norm.exp - ck.t[k].exp, &sat);
    out.r[k] = fx::sat32(int64_t{db_over_n} - fx::shr_round(int64_t{f} * dn_over_n, fx::kValueFrac), &sat);
  }
  out.saturated = sat;
}

}  // namespace

void stereo_measurement(const ColumnProfile& p0, const ColumnProfile& p1, const KernelBank& bank,
                        StereoMeasurement& out) {
  CameraOutputs c0, c1;
  camera_outputs(p0, bank.cam[0], bank.count, c0);
  camera_outputs(p1, bank.cam[1], bank.count, c1);
  out.count = bank.count;
  out.no_light = c0.no_light || c1.no_light;
  bool sat = c0.saturated || c1.saturated;
  for (uint8_t k = 0; k < bank.count; ++k) {
    out.mid[k] = static_cast<ValueQ28>(fx::shr_round(int64_t{c0.f[k]} + c1.f[k], 1));
    out.diff[k] = fx::sat32(int64_t{c1.f[k]} - c0.f[k], &sat);
    out.rot[k] = static_cast<SlopeQ20>(fx::shr_round(int64_t{c0.r[k]} + c1.r[k], 1));
    out.curv[k] = static_cast<CurvQ12>(fx::shr_round(int64_t{c0.c[k]} + c1.c[k], 1));
  }
  out.saturated = sat;
  out.clipped = p0.clipped + p1.clipped;
}

}  // namespace lumavel
