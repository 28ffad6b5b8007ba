#include "lumavel/core/measurement.hpp"

#include "lumavel/core/estimator_params.hpp"
#include "lumavel/core/imath.hpp"
#include "lumavel/core/kernel_dot.hpp"

namespace lumavel {
namespace {

using namespace kdot;

// The rotation term's edge-row correction (measurement.hpp), 2^kEdgeScaleBits x per column:
// C = lean x E, |lean| <= 4 (Q24), |4 E| < 2^18: |C| < 2^24.3 (times 2^31 x 160 < 2^63).
// (A Q8 profile with edges, the photometric match's mapped one: |4 E| < 2^26,
// C is 2^-2 x lean x E in its units, the same size.)
constexpr int kEdgeScaleBits = 6;  // C is 2^6 x lean x E
int edge_scale_bits(const ColumnProfile& p) { return p.q8 ? kEdgeScaleBits - 8 : kEdgeScaleBits; }
template <int Shift>
void edge_correction_by(const ColumnProfile& p, const LeanQ24* lean, int32_t* c) {
  for (uint16_t u = 0; u < p.width && u < kBandColumns; ++u)
    c[u] = static_cast<int32_t>(fx::shr_round(int64_t{lean[u]} * p.edge4[u], Shift));
}
// (The shift a constant for each kind of profile: a 64-bit shift by a
// variable count is a dozen instructions a column on a 32-bit core.)
void edge_correction(const ColumnProfile& p, const LeanQ24* lean, int32_t* c) {
  if (p.q8)
    edge_correction_by<fx::kLeanFrac + 2 - (kEdgeScaleBits - 8)>(p, lean, c);
  else
    edge_correction_by<fx::kLeanFrac + 2 - kEdgeScaleBits>(p, lean, c);
}

struct CameraOutputs {
  ValueQ28 f[kMaxKernels];
  SlopeQ20 r[kMaxKernels];
  CurvQ12 c[kMaxKernels];
  Normaliser norm;  // N and the reciprocal the ratios took
  bool no_light;
  bool saturated;
};

// F_k = B_k / N (paper eq. 21 applied after the kernel: one division per
// kernel instead of one per pixel); dF/dtheta = (dB - F dN) / N.
// lean: the bank's column leans where the profile has its edge rows (the
// rotation term's correction: measurement.hpp), else nullptr.
// offset: the camera's axis yaw from the kernels' centre (KernelBank::axis_offset), used with lean.
void camera_outputs(const ColumnProfile& p, const CameraKernels& ck, uint8_t count, const LeanQ24* lean,
                    AngleQ28 offset, CameraOutputs& out) {
  out.no_light = false;
  out.saturated = false;
  // The dot products in pairs that share the profile (kdot::dot2): the same sums.
  int64_t n = 0, n_d = 0;
  dot2(ck.norm, ck.norm_d, p, &n, &n_d);
  out.norm = {n, {0, 0}};
  // No light: below a uniform image of kNoLightMeanDn (dark_n is in q8 sums).
  if (n <= 0 || n < (p.q8 ? ck.dark_n : ck.dark_n >> 8)) {
    out.no_light = true;
    for (uint8_t k = 0; k < count; ++k) out.f[k] = out.r[k] = out.c[k] = 0;
    return;
  }
  int64_t bk[kMaxKernels], bd[kMaxKernels], bt[kMaxKernels];
  for (uint8_t k = 0; k < count; ++k) dot2(ck.k[k], ck.d[k], p, &bk[k], &bd[k]);
  uint8_t k = 0;
  for (; k + 2 <= count; k = static_cast<uint8_t>(k + 2)) dot2(ck.t[k], ck.t[k + 1], p, &bt[k], &bt[k + 1]);
  if (k < count) bt[k] = dot(ck.t[k], p);
  // The edge-row correction's dot products (x 2^-kEdgeScaleBits, through each
  // table's own B kernel), or none.
  int64_t en = 0, ek[kMaxKernels] = {};
  if (lean) {
    int32_t c[kBandColumns];
    edge_correction(p, lean, c);
    k = 0;
    for (; k + 2 <= count; k = static_cast<uint8_t>(k + 2))
      dot_values2(ck.k[k], ck.k[k + 1], c, p.width, &ek[k], &ek[k + 1]);
    if (k < count)
      dot_values2(ck.k[k], ck.norm, c, p.width, &ek[k], &en);
    else
      en = dot_values(ck.norm, c, p.width);
  }
  const Reciprocal inv = reciprocal(n);
  out.norm.inv = inv;
  bool sat = false;
  // value of table t = w * 2^-(31 + exp): a ratio of two dots carries 2^(exp_n - exp_t).
  const auto corr = [&](int64_t e, const KernelTable& t) {
    return lean ? int64_t{ratio(e, inv, fx::kSlopeFrac - edge_scale_bits(p) + ck.norm.exp - t.exp, &sat)} : 0;
  };
  const int64_t en_over_n = corr(en, ck.norm);  // Q20 per radian
  const SlopeQ20 dn_over_n = fx::sat32(
      int64_t{ratio(n_d, inv, fx::kSlopeFrac + ck.norm.exp - ck.norm_d.exp, &sat)} + en_over_n, &sat);
  const bool offset_taken = lean && offset != 0;
  for (k = 0; k < count; ++k) {
    ValueQ28 f = ratio(bk[k], inv, fx::kValueFrac + ck.norm.exp - ck.k[k].exp, &sat);
    const int64_t ek_over_n = corr(ek[k], ck.k[k]);
    // The camera's F taken back to the centre axis: F - offset (C_k - F C_N) / N
    // (|offset| < 2^30 Q28, the bracket < 2^32 Q20: the product < 2^62).
    if (offset_taken) {
      const int64_t lean_slope = ek_over_n - fx::shr_round(int64_t{f} * en_over_n, fx::kValueFrac);
      f = fx::sat32(int64_t{f} - fx::shr_round(int64_t{offset} * lean_slope, fx::kSlopeFrac), &sat);
    }
    const SlopeQ20 db_over_n = fx::sat32(
        int64_t{ratio(bd[k], inv, fx::kSlopeFrac + ck.norm.exp - ck.d[k].exp, &sat)} + ek_over_n, &sat);
    out.f[k] = f;
    // T is a 16-bit table: value = w * 2^-(15 + exp), a 2^16 larger step than a q31 table.
    out.c[k] = ratio(bt[k], inv, fx::kCurvFrac + ck.norm.exp - ck.t[k].exp + 16, &sat);
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
static_assert(kSigmaW2MinQ24 >= (int64_t{1} << 20), "the root's division below needs s2 <= 4 (div_q_short: q <= 30)");

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
  // 15-bit root, then one division (32-bit work: the root is below 2^16 and
  // s2 <= 4, as u >= 2^20, for div_q_short).
  int s2 = 0;
  while (u < (int64_t{1} << 28)) {
    u *= 4;
    ++s2;
  }
  const uint32_t root = fx::isqrt32(static_cast<uint32_t>(u));  // sqrt(u) * 2^(12 + s2), in [2^14, 2^15)
  const int64_t inv_w = fx::div_q_short(sigma, root, 8 + s2);         // Q24 rad
  const int64_t a0 = clamp30(int64_t{c0.f[k]} - dc0), a1 = clamp30(int64_t{c1.f[k]} - dc1);
  const int64_t b0 = clamp30(-fx::shr_round(r0 * inv_w, 16)), b1 = clamp30(-fx::shr_round(r1 * inv_w, 16));
  int64_t re = a1 * a0 + b1 * b0, im = b1 * a0 - a1 * b0;  // Q56, |.| < 2^61
  // Halved (toward zero) until both fit 32 bits: the bulk in one shift of the
  // magnitudes (k halvings toward zero are one truncated division by 2^k), the
  // last one or two as before.
  const uint64_t mag = static_cast<uint64_t>(re < 0 ? -re : re) | static_cast<uint64_t>(im < 0 ? -im : im);
  if (mag >> 32) {
    const int halvings = kdot::bit_length(mag) - 32;
    re = re < 0 ? -((-re) >> halvings) : re >> halvings;
    im = im < 0 ? -((-im) >> halvings) : im >> halvings;
  }
  while (re >= (int64_t{1} << 31) || re < -(int64_t{1} << 31) || im >= (int64_t{1} << 31) || im < -(int64_t{1} << 31)) {
    re /= 2;
    im /= 2;
  }
  return fx::atan2_fast(static_cast<int32_t>(im), static_cast<int32_t>(re)) / 2;
}

}  // namespace

void stereo_measurement(const ColumnProfile& p0, const ColumnProfile& p1, const KernelBank& bank,
                        const PhotometricBalance* balance, StereoMeasurement& out, kdot::Normaliser* norm1) {
  CameraOutputs c0, c1;
  camera_outputs(p0, bank.cam[0], bank.count, bank.leaning && p0.edges ? bank.lean[0] : nullptr, bank.axis_offset[0], c0);
  camera_outputs(p1, bank.cam[1], bank.count, bank.leaning && p1.edges ? bank.lean[1] : nullptr, bank.axis_offset[1], c1);
  if (norm1) *norm1 = c1.norm;
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
