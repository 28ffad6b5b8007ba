#include "lumavel/core/kernel_bank.hpp"

#include <algorithm>

#include "lumavel/core/estimator_params.hpp"
#include "lumavel/core/imath.hpp"

namespace lumavel {
namespace {

constexpr int kSimpsonIntervals = params::kKernelSimpsonIntervals;
static_assert(kSimpsonIntervals >= 2 && kSimpsonIntervals % 2 == 0, "Simpson's rule needs an even count");
constexpr int64_t kSimpsonWeightSum = 3 * kSimpsonIntervals;
constexpr int kPoints = kSimpsonIntervals + 1;

// Simpson's weights 1, 4, 2, 4, ..., 2, 4, 1 (their sum is kSimpsonWeightSum).
constexpr int simpson_weight(int j) { return j == 0 || j == kSimpsonIntervals ? 1 : (j % 2 == 1 ? 4 : 2); }

// The kernels' cut-off in Q24 sigmas; the Hermite recursion below keeps
// s * He_k inside int64 for |s| up to 7.
constexpr int64_t kCutoffQ24 = fx::q_of(params::kKernelCutoffSigma, 24);
static_assert(kCutoffQ24 <= (int64_t{7} << 24), "gaussian_triple is sized for |s| <= 7");

// phi_n, phi_(n+1) and phi_(n+3) at s (Q7.24), Q1.30 (phi_(n+3): Q4.27,
// |phi_6| peaks at 15). Each product He * e is the value itself times 2^54
// (< 2^58), so it cannot overflow however large He grows.
void gaussian_triple(int order, int64_t s, int32_t* phi_n, int32_t* phi_n1, int32_t* phi_n3) {
  const int64_t one = int64_t{1} << 24;
  if (s > kCutoffQ24 || s < -kCutoffQ24) {
    *phi_n = 0;
    *phi_n1 = 0;
    *phi_n3 = 0;
    return;
  }
  const int32_t e = fx::exp_neg_q27((s * s) >> 22);  // exp(-s^2/2), Q1.30
  // He_0..He_4 in Q24 and He_5, He_6 in Q20 by He_(k+1) = s He_k - k He_(k-1);
  // the lower precision of the last two keeps s * He_k inside int64 (|s| <= 7).
  int64_t he[7];
  he[0] = one;
  he[1] = s;
  for (int k = 1; k < 4; ++k) he[k + 1] = ((s * he[k]) >> 24) - k * he[k - 1];
  const int64_t s20 = s / 16;
  he[5] = ((s20 * (he[4] / 16)) >> 20) - 4 * (he[3] / 16);
  he[6] = ((s20 * he[5]) >> 20) - 5 * (he[4] / 16);
  // phi_n = (-1)^n He_n e^{-s^2/2}
  const int64_t a = fx::shr_round(he[order] * e, 24);
  const int64_t b = fx::shr_round(he[order + 1] * e, 24);
  const int n3 = order + 3;
  const int64_t c = n3 <= 4 ? fx::shr_round(he[n3] * e, 27) : fx::shr_round(he[n3] * e, 23);
  *phi_n = static_cast<int32_t>(order % 2 == 0 ? a : -a);
  *phi_n1 = static_cast<int32_t>((order + 1) % 2 == 0 ? b : -b);
  *phi_n3 = static_cast<int32_t>((order + 3) % 2 == 0 ? c : -c);
}

// Body yaw of column edge u: the pinhole edge plus the lens correction (Q15 -> Q28).
AngleQ28 edge_yaw(const CameraGeometry& g, const EdgeOffsetQ15* lens, uint16_t u) {
  // atan of the exact ratio (x / fu, both Q16 px): no rounded tangent.
  const int64_t x = (int64_t{u} << 16) - (int64_t{1} << 15) - g.cu;
  const AngleQ28 pin = static_cast<AngleQ28>(g.axis_yaw + g.u_sign * fx::atan2_i32(static_cast<int32_t>(x), g.fu));
  constexpr int kShift = fx::kAngleFrac - fx::kEdgeOffsetFrac;
  return lens == nullptr ? pin : static_cast<AngleQ28>(pin + lens[u] * (int32_t{1} << kShift));
}

// Column u's elevation scale, Q1.30: the lens table's where there is one,
// else the pinhole's cos(a_u), a_u the yaw of the column's centre (the mean
// of its edges) from the camera's axis; 0 where a column is turned to or past
// 90 deg from the axis (the bank then does not band).
int32_t column_cos_q30(const EstimatorConfig& cfg, int cam, uint16_t u) {
  if (cfg.elevation_scale[cam])
    return static_cast<int32_t>(int64_t{cfg.elevation_scale[cam][u]} << (30 - fx::kElevationScaleFrac));
  const CameraGeometry& g = cfg.cam[cam];
  const EdgeOffsetQ15* lens = cfg.edge_offsets[cam];
  const int64_t mid = (int64_t{edge_yaw(g, lens, u)} + edge_yaw(g, lens, static_cast<uint16_t>(u + 1))) / 2;
  const int64_t a = mid - g.axis_yaw;
  if (a >= fx::kPiQ28 / 2 || a <= -(fx::kPiQ28 / 2)) return 0;
  const int32_t c = fx::cos_q30(static_cast<AngleQ28>(a));
  return c > 0 ? c : 0;
}

// Both cameras' mean, Q1.30; 0 where either turns a column to 90 deg.
int32_t mean_column_cos_q30(const EstimatorConfig& cfg, uint16_t u) {
  const int32_t c0 = column_cos_q30(cfg, 0, u);
  const int32_t c1 = column_cos_q30(cfg, 1, u);
  return c0 > 0 && c1 > 0 ? static_cast<int32_t>((int64_t{c0} + c1) / 2) : 0;
}

// The common elevation band (kernel_bank.hpp), one for both cameras (their
// column cos(a_u) averaged: equal for twin cameras, whatever their
// misalignment, since a_u is from each camera's own axis), with square
// pixels: the column that sees the narrowest band, (H/2) cos(a_min) / f in
// tan E, sets it. Column u then sums b_u = (H/2) cos(a_min) / cos(a_u) rows
// either side of the centre row (Q8 rows). False when a band would be under
// two rows (a line scan, or a lens so wide that the centre column keeps
// almost nothing): every column then sums all rows, unweighted.
bool build_band(const EstimatorConfig& cfg, ColumnBand& band) {
  if (cfg.height < 2 || kBandColumns == 1) return false;
  int32_t cos_min = int32_t{1} << 30;
  for (uint16_t u = 0; u < cfg.width; ++u) cos_min = std::min(cos_min, mean_column_cos_q30(cfg, u));
  if (cos_min <= 0) return false;
  const int64_t half_q8 = int64_t{cfg.height} * 128;
  for (uint16_t u = 0; u < cfg.width && u < kBandColumns; ++u) {
    const int64_t c = mean_column_cos_q30(cfg, u);
    int64_t b_q8 = (half_q8 * cos_min + c / 2) / c;  // c >= cos_min > 0
    if (b_q8 > half_q8) b_q8 = half_q8;
    if (b_q8 < 256) return false;
    const int64_t excluded_q8 = half_q8 - b_q8;
    const int64_t first = (excluded_q8 + 255) >> 8;
    band.first[u] = static_cast<uint8_t>(first);
    band.edge_q8[u] = static_cast<uint8_t>(first * 256 - excluded_q8);
  }
  return true;
}

int64_t clamp_lean(int64_t v, int64_t lim) { return v > lim ? lim : (v < -lim ? -lim : v); }

// Column u's lean, -d ln s / d(yaw), s the elevation scale (column_cos_q30):
// a central difference over the column's neighbours (one-sided at the ends),
// in body yaw. For a pinhole s = cos(a_u) and the lean is tan(a_u) (to 0.03 %
// at 40 columns / 60 deg inside, 4 % on the outermost columns). 0 where a
// column is turned to 90 deg; clamped to +-4 (LeanQ24).
LeanQ24 column_lean_q24(const EstimatorConfig& cfg, int cam, uint16_t u) {
  const uint16_t lo = u > 0 ? static_cast<uint16_t>(u - 1) : u;
  const uint16_t hi = u + 1 < cfg.width ? static_cast<uint16_t>(u + 1) : u;
  const int64_t s = column_cos_q30(cfg, cam, u), s_lo = column_cos_q30(cfg, cam, lo), s_hi = column_cos_q30(cfg, cam, hi);
  const CameraGeometry& g = cfg.cam[cam];
  const EdgeOffsetQ15* lens = cfg.edge_offsets[cam];
  const auto mid = [&](uint16_t c) { return (int64_t{edge_yaw(g, lens, c)} + edge_yaw(g, lens, static_cast<uint16_t>(c + 1))) / 2; };
  const int64_t dpsi = mid(hi) - mid(lo);  // Q28
  if (s <= 0 || s_lo <= 0 || s_hi <= 0 || dpsi == 0) return 0;
  const int64_t rel = fx::div_q(s_hi - s_lo, s, 30);  // ds / s, Q30 (|.| < 2)
  constexpr int64_t kMax = int64_t{4} << fx::kLeanFrac;
  return static_cast<LeanQ24>(clamp_lean(fx::div_q(-rel, dpsi, fx::kLeanFrac + fx::kAngleFrac - 30), kMax));
}

// Raw column integrals, in sigma units, Q3.28, written into the tables'
// storage before quantisation (no scratch memory: the edges are computed as
// they are needed, so no edge table is kept in RAM), weighted by cos(a_u)
// when banded:
//   K = Int phi_n(s) ds,  D = -Int phi_(n+1)(s) ds,  T = -Int phi_(n+3)(s) ds
void integrate(const EstimatorConfig& cfg, int cam, int64_t centre, bool banded, const KernelSpec& k,
               KernelTable* kk, KernelTable* dd, KernelTable* tt) {
  const CameraGeometry& g = cfg.cam[cam];
  const EdgeOffsetQ15* lens = cfg.edge_offsets[cam];
  const uint16_t width = cfg.width;
  int64_t next = edge_yaw(g, lens, 0);
  for (uint16_t u = 0; u < width; ++u) {
    const int64_t lo = next, hi = edge_yaw(g, lens, static_cast<uint16_t>(u + 1));
    next = hi;
    // (kBandColumns: a line-scan build drops the band's code.)
    const int64_t cos_u = kBandColumns > 1 && banded ? column_cos_q30(cfg, cam, u) : int64_t{1} << 30;
    int64_t acc_k = 0, acc_d = 0, acc_t = 0;
    for (int j = 0; j < kPoints; ++j) {
      const int64_t psi = lo + (hi - lo) * j / kSimpsonIntervals;
      const int64_t s = fx::div_q(psi - centre, k.sigma, 24);
      int32_t pn = 0, pn1 = 0, pn3 = 0;
      gaussian_triple(k.order, s, &pn, &pn1, &pn3);
      const int64_t wj = simpson_weight(j);
      acc_k += wj * pn;
      acc_d += wj * pn1;
      acc_t += wj * pn3;  // Q27
    }
    const int64_t ds = fx::div_q(hi > lo ? hi - lo : lo - hi, k.sigma, 24);  // Q24
    // Saturated to int32 first (as the tables are stored), so that the Q30
    // weight's product stays below 2^61; cos_u = 2^30 leaves v as it was.
    const auto weighted = [cos_u](int64_t v) { return fx::sat32(fx::shr_round(int64_t{fx::sat32(v)} * cos_u, 30)); };
    if (kk) kk->w[u] = weighted(fx::shr_round(acc_k * ds, 26) / kSimpsonWeightSum);
    if (dd) dd->w[u] = weighted(-(fx::shr_round(acc_d * ds, 26) / kSimpsonWeightSum));
    if (tt) tt->w[u] = weighted(-(fx::shr_round(acc_t * ds, 24) / kSimpsonWeightSum));  // Q3.27
  }
  for (uint16_t u = width; u < kMaxColumns; ++u) {
    if (kk) kk->w[u] = 0;
    if (dd) dd->w[u] = 0;
    if (tt) tt->w[u] = 0;
  }
}

// Re-scales raw Q28 values in place to value = raw / den (den Q28), as a
// full-range q31 table with a power-of-two exponent.
void quantise(int64_t den, uint16_t width, KernelTable& t) {
  int64_t peak = 0;
  for (uint16_t u = 0; u < width; ++u) {
    const int64_t a = t.w[u] < 0 ? -int64_t{t.w[u]} : t.w[u];
    if (a > peak) peak = a;
  }
  // Largest exponent that keeps the peak below 2^31.
  int e = 20;
  for (; e > -40; --e) {
    bool sat = false;
    const int32_t w = fx::div_q(peak, den, 31 + e, &sat);
    if (!sat && w < fx::kInt32Max) break;
  }
  t.exp = static_cast<int8_t>(e);
  for (uint16_t u = 0; u < width; ++u) t.w[u] = fx::div_q(t.w[u], den, 31 + e);
}

// The same for a 16-bit table, from raw Q28 values in `raw`.
void quantise16(int64_t den, uint16_t width, const KernelTable& raw, KernelTable16& t) {
  int64_t peak = 0;
  for (uint16_t u = 0; u < width; ++u) {
    const int64_t a = raw.w[u] < 0 ? -int64_t{raw.w[u]} : raw.w[u];
    if (a > peak) peak = a;
  }
  int e = 20;
  for (; e > -40; --e) {
    bool sat = false;
    const int32_t w = fx::div_q(peak, den, 15 + e, &sat);
    if (!sat && w < 32767) break;
  }
  t.exp = static_cast<int8_t>(e);
  for (uint16_t u = 0; u < width; ++u) t.w[u] = static_cast<int16_t>(fx::div_q(raw.w[u], den, 15 + e));
  for (uint16_t u = width; u < kMaxColumns; ++u) t.w[u] = 0;
}

int64_t sum(const KernelTable& t, uint16_t width) {
  int64_t s = 0;
  for (uint16_t u = 0; u < width; ++u) s += t.w[u];
  return s;
}

// Sum of squares in Q48 (values rounded to Q24 first: 160 columns of |v| < 8
// stay below 2^62 even after the multiplication by the width).
uint64_t sum_sq_q48(const KernelTable& t, uint16_t width) {
  uint64_t s = 0;
  for (uint16_t u = 0; u < width; ++u) {
    const int64_t v = fx::shr_round(t.w[u], 4);
    s += static_cast<uint64_t>(v * v);
  }
  return s;
}

// Builds K and D of one kernel for both cameras with one shared scale, so
// that F1 - F0 compares like with like. unit_l1: the normaliser (sum K = 1);
// otherwise sum K^2 = 1/width, which gives every kernel the same pixel-noise
// variance, so that the least squares over kernels weighs them fairly.
void build_kernel(const EstimatorConfig& cfg, int64_t centre, bool banded,
                  const KernelSpec& spec, bool unit_l1, KernelTable* k_out[2],
                  KernelTable* d_out[2], KernelTable16* t_out[2]) {
  const uint16_t w = cfg.width;
  for (int i = 0; i < 2; ++i)
    integrate(cfg, i, centre, banded, spec, k_out[i], d_out[i], nullptr);
  int64_t norm = 0;  // Q28
  if (unit_l1) {
    norm = (sum(*k_out[0], w) + sum(*k_out[1], w)) / 2;
  } else {
    // sqrt(width * mean sum of squares) in one root: Q48 -> Q24 -> Q28.
    const uint64_t sq = (sum_sq_q48(*k_out[0], w) + sum_sq_q48(*k_out[1], w)) / 2 * w;
    norm = static_cast<int64_t>(fx::isqrt64(sq)) * 16;
  }
  if (norm <= 0) norm = 1;
  // D per radian: divide by sigma as well (Q28 * Q28 -> Q28).
  int64_t norm_sigma = fx::shr_round(norm * spec.sigma, 28);
  if (norm_sigma <= 0) norm_sigma = 1;
  // T per radian cubed: raw Q27 values over norm * sigma^3.
  int64_t norm_sigma3 = fx::shr_round(fx::shr_round(norm_sigma * spec.sigma, 28) * spec.sigma, 28);
  norm_sigma3 = norm_sigma3 > 1 ? norm_sigma3 / 2 : 1;  // Q27 over Q28 -> same scale as the others
  for (int i = 0; i < 2; ++i) {
    if (t_out[i]) {
      // T in a scratch table, then narrowed to 16 bits (a second pass over
      // the columns at configuration time saves a q31 table per kernel).
      KernelTable raw;
      integrate(cfg, i, centre, banded, spec, nullptr, nullptr, &raw);
      quantise16(norm_sigma3, w, raw, *t_out[i]);
    }
    quantise(norm, w, *k_out[i]);
    quantise(norm_sigma, w, *d_out[i]);
  }
}

}  // namespace

int32_t gaussian_derivative_q30(int order, int32_t s_q24) {
  int32_t a = 0, b = 0, c = 0;
  gaussian_triple(order, s_q24, &a, &b, &c);
  return a;
}

void pinhole_column_edges(const CameraGeometry& g, uint16_t width, AngleQ28* edges) {
  for (uint16_t u = 0; u <= width; ++u) edges[u] = edge_yaw(g, nullptr, u);
}

void column_edge_yaws(const CameraGeometry& g, const EdgeOffsetQ15* offsets, uint16_t width, AngleQ28* edges) {
  for (uint16_t u = 0; u <= width; ++u) edges[u] = edge_yaw(g, offsets, u);
}

void build_kernel_bank(const EstimatorConfig& cfg, KernelBank& bank) {
  bank.width = cfg.width;
  bank.count = cfg.kernel_count;
  bank.banded = (cfg.options & kOptionElevationBand) != 0 && build_band(cfg, bank.band);
  const int64_t centre = (int64_t{cfg.cam[0].axis_yaw} + cfg.cam[1].axis_yaw) / 2;
  KernelTable* k_out[2] = {&bank.cam[0].norm, &bank.cam[1].norm};
  KernelTable* d_out[2] = {&bank.cam[0].norm_d, &bank.cam[1].norm_d};
  KernelTable16* none[2] = {nullptr, nullptr};
  build_kernel(cfg, centre, bank.banded, cfg.normaliser, true, k_out, d_out, none);
  for (int k = 0; k < cfg.kernel_count; ++k) {
    KernelTable* kk[2] = {&bank.cam[0].k[k], &bank.cam[1].k[k]};
    KernelTable* dd[2] = {&bank.cam[0].d[k], &bank.cam[1].d[k]};
    KernelTable16* tt[2] = {&bank.cam[0].t[k], &bank.cam[1].t[k]};
    build_kernel(cfg, centre, bank.banded, cfg.kernels[k], false, kk, dd, tt);
  }
  for (int k = 0; k < cfg.kernel_count; ++k) bank.sigma[k] = cfg.kernels[k].sigma;
  bank.rings = radial_rings(cfg.width, cfg.height);
  bank.leaning = !bank.banded && kBandColumns > 1 && cfg.height >= 2;
  for (int i = 0; i < 2; ++i) {
    for (uint16_t u = 0; u < kBandColumns; ++u)
      bank.lean[i][u] = bank.leaning && u < cfg.width ? column_lean_q24(cfg, i, u) : 0;
    // (|axis - centre| is half the axes' difference: < 2^31 for two AngleQ28)
    bank.axis_offset[i] = static_cast<AngleQ28>(int64_t{cfg.cam[i].axis_yaw} - centre);
  }
  // F of a uniform image: each column sums its band's rows of one value.
  for (int i = 0; i < 2; ++i) {
    const auto uniform_dot = [&](const KernelTable& t) {
      int64_t s = 0;  // |w| < 2^31, rows < 2^15 in Q8, 160 columns: < 2^54
      for (uint16_t u = 0; u < cfg.width; ++u) s += int64_t{t.w[u]} * band_rows_q8(bank.column_band(), cfg.height, u);
      return s;
    };
    const int64_t n = uniform_dot(bank.cam[i].norm);
    bank.cam[i].dark_n = n * params::kNoLightMeanDn;  // (n < 2^54, times 2: below 2^56)
    for (int k = 0; k < cfg.kernel_count; ++k)
      bank.dc[i][k] = fx::div_q(uniform_dot(bank.cam[i].k[k]), n > 0 ? n : 1,
                                fx::kValueFrac + bank.cam[i].norm.exp - bank.cam[i].k[k].exp);
  }
}

}  // namespace lumavel
