#include "lumavel/core/photometric_match.hpp"

#if LUMAVEL_MATCH_FRAMES > 0  // (a line-scan build leaves it out: limits.hpp)

#include "lumavel/core/imath.hpp"
#include "lumavel/core/kernel_dot.hpp"


namespace lumavel {
namespace {

using namespace params;

constexpr int kQ = 30;  // p and the column coordinates
constexpr int64_t kOne = int64_t{1} << kQ;
constexpr int kMemoryLog2 = kMatchMemoryLog2;
constexpr int32_t kMemorySamples = int32_t{1} << kMemoryLog2;
constexpr int64_t kMinSpeedQ16 = fx::q_of(kMatchMinSpeed, fx::kSpeedFrac);
// The prior's precision per unit of parameter (beta in kMatchOffsetUnitDn).
constexpr int64_t kInvPrior2[kMatchParams] = {
    fx::q_of(kMatchSampleCorrelation / (kMatchPriorTilt * kMatchPriorTilt), 0),
    fx::q_of(kMatchSampleCorrelation / (kMatchPriorVignetting * kMatchPriorVignetting), 0),
    fx::q_of(kMatchSampleCorrelation * kMatchOffsetUnitDn * kMatchOffsetUnitDn / (kMatchPriorOffsetDn * kMatchPriorOffsetDn), 0)};
constexpr int64_t kMaxParamQ30[kMatchParams] = {fx::q_of(kMatchMaxShape, kQ), fx::q_of(kMatchMaxShape, kQ),
                                                fx::q_of(kMatchMaxOffsetDn / kMatchOffsetUnitDn, kQ)};
static_assert(fx::q_of(kMatchOffsetUnitDn, 8) == 64 << 8, "beta in Q30 units of 64 DN is beta in Q24 DN");
constexpr int kBetaDnFrac = 24;
constexpr int64_t kExplainedNoneQ16 = fx::q_of(kMatchExplainedNone, 16);
constexpr int64_t kExplainedSpanQ16 = fx::q_of(kMatchExplainedAll - kMatchExplainedNone, 16);
constexpr int64_t kOffsetUnitDn = fx::q_of(kMatchOffsetUnitDn, 0);
constexpr int64_t kHeld = int64_t{1} << 22;  // |J|, |z| <= 4 in Q20
// A Q8 column sum stays below 2^23 (the dot products' bound, kernel_dot.hpp).
constexpr int64_t kMaxQ8Sum = (int64_t{1} << 23) - 1;
static_assert(sizeof(ColumnSum) == 4, "the mapped profile is Q8: 32-bit sums");

int64_t abs64(int64_t v) { return v < 0 ? -v : v; }
int32_t hold(int64_t v) { return static_cast<int32_t>(v > kHeld ? kHeld : (v < -kHeld ? -kHeld : v)); }

// x_u = (2u + 1 - W) / W in Q30: the column's centre across the image, as
// (2u + 1 - W) times one step 2^30 / W (one 32-bit division a call instead
// of one 64-bit division per column; within W / 2 of 2^-30 of the exact x),
// walked from x_0 by 2 steps a column (the same integers, no multiply).
// |x_u| <= (W - 1) 2^30 / W < 2^30: a 32-bit value, so that its products are
// 32 x 32 -> 64 bits (one multiply on a 32-bit core, not a 64-bit one).
struct ColumnX {
  int32_t first, stride;  // x_0, x_(u+1) - x_u
  explicit ColumnX(uint16_t width) {
    const int32_t step = static_cast<int32_t>(static_cast<uint32_t>(kOne) / width);
    first = (1 - width) * step;
    stride = 2 * step;
  }
};

// The rows column u sums, in the profile's units (a uniform image of value
// 1 sums to this).
int64_t rows_in_sum(const ColumnProfile& p, const ColumnBand* band, uint16_t height, uint16_t u) {
  return p.q8 ? int64_t{band_rows_q8(band, height, u)} : int64_t{height};
}

// x^2 in Q30 (|x| < 2^30: below 2^30 too).
int32_t square_q30(int32_t x) { return static_cast<int32_t>(fx::shr_round(int64_t{x} * x, kQ)); }

int64_t gain_q30(const int32_t* p, int32_t x) {
  return kOne + fx::shr_round(int64_t{p[0]} * x, kQ) + fx::shr_round(int64_t{p[1]} * square_q30(x), kQ);
}

int64_t lerp(int64_t a, int64_t b, int64_t u_q16) { return a + fx::shr_round((b - a) * u_q16, 16); }

}  // namespace

void PhotometricMatch::reset() { *this = PhotometricMatch{}; }

void PhotometricMatch::apply(ColumnProfile& p1, const ColumnBand* band, uint16_t height, const RadialSums* radial) {
  // The mapped sums keep 8 fractional bits (a plain profile becomes Q8): a
  // whole-number rounding would add noise that the twin does not have.
  const int up = p1.q8 ? 0 : 8;
  if (p_[0] == 0 && p_[1] == 0 && p_[2] == 0) {  // twins (the usual case): the same bits as below, g = 1
    for (uint16_t u = 0; u < p1.width; ++u) {
      const int64_t s = int64_t{p1.sum[u]} * (int64_t{1} << up);
      p1.sum[u] = static_cast<ColumnSum>(s < 0 ? 0 : (s > kMaxQ8Sum ? kMaxQ8Sum : s));
      if (p1.edges && u < kBandColumns) p1.edge4[u] = static_cast<int32_t>(int64_t{p1.edge4[u]} * (int64_t{1} << up));
    }
    p1.plain_x256 = up == 8;  // (no sum reaches kMaxQ8Sum: plain sums are below 2^15)
    p1.q8 = true;
    return;
  }
  const ColumnX column_x(p1.width);
  int32_t x = column_x.first;
  for (uint16_t u = 0; u < p1.width; ++u, x += column_x.stride) {
    const int64_t g = gain_q30(p_, x);
    // (sum - rows beta) in Q8 units of the mapped profile, then times g: < 2^31 * 2^31
    const int64_t t = fx::shr_round(int64_t{p1.sum[u]} * (int64_t{1} << kBetaDnFrac) - rows_in_sum(p1, band, height, u) * p_[2],
                                    kBetaDnFrac - up);
    int64_t s = fx::shr_round(t * g, kQ);
    if (radial) {  // the rows' share of the vignetting: a2 (sum_y2 - rows_y2 beta), Q8 (< 2^53 before the shift)
      const int64_t t2 = fx::shr_round(
          int64_t{radial->sum_y2[u]} * (int64_t{1} << kBetaDnFrac) - int64_t{radial->rows_y2_q8} * p_[2], kBetaDnFrac);
      s += fx::shr_round(t2 * p_[1], kQ);
    }
    s = s < 0 ? 0 : (s > kMaxQ8Sum ? kMaxQ8Sum : s);
    p1.sum[u] = static_cast<ColumnSum>(s);
    if (p1.edges && u < kBandColumns)
      p1.edge4[u] = static_cast<int32_t>(fx::shr_round(int64_t{p1.edge4[u]} * (int64_t{1} << up) * g, kQ));
  }
  p1.plain_x256 = false;
  p1.q8 = true;
}

void PhotometricMatch::jacobian(const ColumnProfile& p1, const ColumnBand* band, uint16_t height,
                                const RadialSums* radial, const CameraKernels& ck, uint8_t count, const ValueQ28* f1,
                                MatchJac& jac, const kdot::Normaliser* norm1) {
  const int64_t n = norm1 ? norm1->n : kdot::dot(ck.norm, p1);
  for (uint8_t k = 0; k < count; ++k)
    for (int j = 0; j < kMatchParams; ++j) jac[k][j] = 0;
  if (n <= 0) return;
  const kdot::Reciprocal inv = norm1 && norm1->inv.mant != 0 ? norm1->inv : kdot::reciprocal(n);
  bool sat = false;
  // d sum' / d p_j per column, in the sums' units: a1 and a2 from the image,
  // beta's from the rows alone (its dot products kept while p and the
  // geometry stay: for twins p stays 0, so they are taken once).
  int32_t du[2][kMaxColumns];
  const ColumnX column_x(p1.width);
  int32_t x = column_x.first;
  for (uint16_t u = 0; u < p1.width; ++u, x += column_x.stride) {
    du[0][u] = static_cast<int32_t>(fx::shr_round(int64_t{p1.sum[u]} * x, kQ));
    du[1][u] = static_cast<int32_t>(fx::shr_round(int64_t{p1.sum[u]} * square_q30(x), kQ) +
                                    (radial ? radial->sum_y2[u] : 0));
  }
  const bool beta_kept = beta_dots_.valid && beta_dots_.width == p1.width && beta_dots_.height == height &&
                         beta_dots_.q8 == p1.q8 && beta_dots_.count == count && beta_dots_.p[0] == p_[0] &&
                         beta_dots_.p[1] == p_[1] && beta_dots_.p[2] == p_[2] && beta_dots_.radial == (radial != nullptr) &&
                         beta_dots_.rows_y2 == (radial ? radial->rows_y2_q8 : 0);
  if (!beta_kept) {
    int32_t db[kMaxColumns];
    x = column_x.first;
    for (uint16_t u = 0; u < p1.width; ++u, x += column_x.stride)
      db[u] = static_cast<int32_t>(-fx::shr_round(
          (rows_in_sum(p1, band, height, u) * gain_q30(p_, x) +
           (radial ? int64_t{radial->rows_y2_q8} * p_[1] : 0)) * kOffsetUnitDn,
          kQ));
    beta_dots_ = BetaDots{true, p1.q8, count, p1.width, height, {p_[0], p_[1], p_[2]}, radial != nullptr,
                          radial ? radial->rows_y2_q8 : 0,
                          kdot::dot_values(ck.norm, db, p1.width), {}};
    for (uint8_t k = 0; k < count; ++k) beta_dots_.k[k] = kdot::dot_values(ck.k[k], db, p1.width);
  }
  // The image's two columns of derivatives against each table in one pass
  // where the core allows (kdot::dot_values_shared: each weight loaded once for both).
  static_assert(kMatchParams == 3, "two image parameters and the black level");
  int64_t dots_norm[2], dots_k[2][kMaxKernels];
  kdot::dot_values_shared(ck.norm, du[0], du[1], p1.width, &dots_norm[0], &dots_norm[1]);
  for (uint8_t k = 0; k < count; ++k)
    kdot::dot_values_shared(ck.k[k], du[0], du[1], p1.width, &dots_k[0][k], &dots_k[1][k]);
  for (int j = 0; j < kMatchParams; ++j) {
    // dF/dp = (dB/dp - F dN/dp) / N
    const int64_t dot_norm = j < 2 ? dots_norm[j] : beta_dots_.norm;
    const int64_t dn = kdot::ratio(dot_norm, inv, fx::kValueFrac, &sat);
    for (uint8_t k = 0; k < count; ++k) {
      const int64_t dot_k = j < 2 ? dots_k[j][k] : beta_dots_.k[k];
      const int64_t db = kdot::ratio(dot_k, inv, fx::kValueFrac + ck.norm.exp - ck.k[k].exp, &sat);
      jac[k][j] = fx::sat32(db - fx::shr_round(int64_t{f1[k]} * dn, fx::kValueFrac));
    }
  }
}

bool PhotometricMatch::learn(const MatchInput& in) {
  for (int j = 0; j < kMatchParams; ++j) p_before_[j] = p_[j];
  if (!in.usable) {
    n_hist_ = 0;
    return false;
  }
  // The frame on the history, cam1's F linearised at p = 0.
  const int slot = n_hist_ < kMatchFrames ? (head_ + n_hist_) % kMatchFrames : head_;
  if (n_hist_ < kMatchFrames)
    ++n_hist_;
  else
    head_ = (head_ + 1) % kMatchFrames;
  Frame& fr = hist_[slot];
  fr.t_ns = in.t_ns;
  fr.heading = in.heading;
  for (uint8_t k = 0; k < in.count; ++k) {
    int64_t jp = 0;
    for (int j = 0; j < kMatchParams; ++j) {
      fr.jac[k][j] = (*in.jac)[k][j];
      jp += int64_t{(*in.jac)[k][j]} * p_[j];
    }
    fr.f[0][k] = in.f[0][k];
    fr.f[1][k] = fx::sat32(int64_t{in.f[1][k]} - fx::shr_round(jp, kQ));
    fr.r[0][k] = in.r[0][k];
    fr.r[1][k] = in.r[1][k];
  }
  const int64_t v = in.v, h = in.baseline;
  if (abs64(v) < kMinSpeedQ16 || h == 0 || n_hist_ < 2) return false;
  // tau = |h| / |V|: h Q24 m, V Q16 m/s -> ns
  const uint64_t tau_ns = static_cast<uint64_t>((abs64(h) * 1000000000) / (abs64(v) * 256));
  const int lead = (v > 0) == (h > 0) ? 1 : 0;
  const int newest = n_hist_ - 1;
  // A: the trail camera now against the lead tau ago; B: the newest lead
  // frame whose tau later lies in the history, against the trail then.
  if (in.t_ns >= tau_ns) sample(newest, 1 - lead, in.t_ns - tau_ns, lead, in.count, in.max_rotation);
  for (int i = newest - 1; i >= 0; --i) {
    const Frame& f = hist_[(head_ + i) % kMatchFrames];
    if (f.t_ns + tau_ns <= in.t_ns) {
      sample(i, lead, f.t_ns + tau_ns, lead, in.count, in.max_rotation);
      break;
    }
  }
  if (samples_ < kMatchFirstSamples || unsolved_ < kMatchSolveSamples) return false;
  unsolved_ = 0;
  return solve();
}

void PhotometricMatch::sample(int fixed, int fixed_cam, uint64_t t_other, int lead, uint8_t count,
                              AngleQ28 max_rotation) {
  const Frame& fx_ = hist_[(head_ + fixed) % kMatchFrames];
  for (int i = 1; i < n_hist_; ++i) {
    const Frame& a = hist_[(head_ + i - 1) % kMatchFrames];
    const Frame& b = hist_[(head_ + i) % kMatchFrames];
    if (t_other < a.t_ns || t_other > b.t_ns) continue;
    const int64_t u = static_cast<int64_t>(((t_other - a.t_ns) << 16) / (b.t_ns - a.t_ns));  // Q16
    const int other = 1 - fixed_cam;
    const bool fixed_leads = fixed_cam == lead;
    const int64_t ho = lerp(a.heading, b.heading, u);
    const int64_t dth = fixed_leads ? ho - fx_.heading : fx_.heading - ho;
    if (abs64(dth) > max_rotation) return;
    // Held to |.| <= 2^22 (Q20): 32-bit values, so that every product below is
    // one 32 x 32 -> 64 multiply on a 32-bit core, not a 64-bit one.
    int32_t z[kMaxKernels], d[kMaxKernels], jj[kMaxKernels][kMatchParams];
    for (uint8_t k = 0; k < count; ++k) {
      const int64_t fo = lerp(a.f[other][k], b.f[other][k], u);
      const int64_t ro = lerp(a.r[other][k], b.r[other][k], u);
      // lead turned to the trail's heading
      const int64_t rl = fixed_leads ? fx_.r[lead][k] : ro;
      const int64_t fl = (fixed_leads ? int64_t{fx_.f[lead][k]} : fo) + fx::shr_round(dth * rl, fx::kSlopeFrac);
      const int64_t ft = fixed_leads ? fo : int64_t{fx_.f[1 - lead][k]};
      const int64_t f1 = lead == 1 ? fl : ft, f0 = lead == 1 ? ft : fl;
      z[k] = hold(fx::shr_round(f0 - f1, 8));  // Q20: J p, cam1's F being linearised at 0
      d[k] = hold(fx::shr_round(int64_t{b.f[other][k]} - a.f[other][k], 8));
      for (int j = 0; j < kMatchParams; ++j)
        jj[k][j] = hold(fx::shr_round(fixed_cam == 1 ? int64_t{fx_.jac[k][j]} : lerp(a.jac[k][j], b.jac[k][j], u), 8));
    }
    // What a timing error adds (the interpolated side's change over its
    // frame) is projected out of the sample: d^ = d / |d| in Q30. (Projecting
    // out the lead's dF/dtheta as well, against a heading error, left two
    // of four rows and doubled the matched walls' error: not done.)
    int64_t dd = 0;
    for (uint8_t k = 0; k < count; ++k) dd += int64_t{d[k]} * d[k];
    int rows = count;
    if (dd > 16) {
      const int64_t norm = fx::isqrt64(static_cast<uint64_t>(dd));  // Q20
      int32_t dh[kMaxKernels];  // |.| <= 2^30
      // (one division: inv = 2^52 / |d| in Q20 is 2^32 / |d|; |d_k| <= |d| keeps d_k inv <= 2^52)
      const int64_t inv = (int64_t{1} << 52) / norm;
      for (uint8_t k = 0; k < count; ++k) dh[k] = static_cast<int32_t>(fx::shr_round(d[k] * inv, 52 - kQ));
      // (|c| <= |d^| |v| < 2^23, |v| after it < 2^24: 32 bits throughout)
      auto project = [&](int32_t* v, int stride) {
        int64_t c = 0;
        for (uint8_t k = 0; k < count; ++k) c += int64_t{dh[k]} * v[k * stride];
        const int32_t c32 = static_cast<int32_t>(fx::shr_round(c, kQ));
        for (uint8_t k = 0; k < count; ++k)
          v[k * stride] -= static_cast<int32_t>(fx::shr_round(int64_t{dh[k]} * c32, kQ));
      };
      project(z, 1);
      for (int j = 0; j < kMatchParams; ++j) project(&jj[0][j], kMatchParams);
      --rows;
    }
    if (samples_ >= kMemorySamples) {
      for (int i2 = 0; i2 < kMatchParams; ++i2) {
        for (int j = 0; j <= i2; ++j) a_[i2][j] -= fx::shr_round(a_[i2][j], kMemoryLog2);
        b_[i2] -= fx::shr_round(b_[i2], kMemoryLog2);
      }
      ee_ -= fx::shr_round(ee_, kMemoryLog2);
      zz_ -= fx::shr_round(zz_, kMemoryLog2);
      dof_ -= fx::shr_round(dof_, kMemoryLog2);
      ee_rows_ -= fx::shr_round(ee_rows_, kMemoryLog2);
    } else {
      ++samples_;
    }
    ++unsolved_;
    for (uint8_t k = 0; k < count; ++k) {
      if (solved_) {
        int64_t e = z[k];
        for (int j = 0; j < kMatchParams; ++j) e -= fx::shr_round(int64_t{jj[k][j]} * est_[j], kQ);
        ee_ += e * e;
      }
      zz_ += int64_t{z[k]} * z[k];
      for (int i2 = 0; i2 < kMatchParams; ++i2) {
        for (int j = 0; j <= i2; ++j) a_[i2][j] += int64_t{jj[k][i2]} * jj[k][j];  // (symmetric: the lower triangle)
        b_[i2] += int64_t{jj[k][i2]} * z[k];
      }
    }
    dof_ += rows;
    if (solved_) ee_rows_ += rows;
    return;
  }
}

bool PhotometricMatch::solve() {
  // The samples' residual variance per row sets the prior's weight.
  const int64_t rows = solved_ ? ee_rows_ : dof_;
  const int64_t free_rows = rows > kMatchParams + 1 ? rows - kMatchParams : 1;
  int64_t s2 = (solved_ ? ee_ : zz_) / free_rows;  // Q40
  if (s2 > (int64_t{1} << 50)) s2 = int64_t{1} << 50;
  int64_t m[kMatchParams][kMatchParams];
  int64_t s[kMatchParams];  // sqrt of the diagonal, Q20
  for (int i = 0; i < kMatchParams; ++i) {
    for (int j = 0; j <= i; ++j) m[i][j] = a_[i][j];
    m[i][i] += s2 * kInvPrior2[i];
    if (m[i][i] <= 0) return false;
    s[i] = fx::isqrt64(static_cast<uint64_t>(m[i][i]));
    if (s[i] == 0) return false;
  }
  // Unit diagonal (Q30), then L D L^T.
  int64_t q[kMatchParams][kMatchParams];  // symmetric: the lower triangle is used
  for (int i = 0; i < kMatchParams; ++i)
    for (int j = 0; j <= i; ++j) q[i][j] = i == j ? kOne : fx::div_q(m[i][j], s[i] * s[j], kQ);
  const int64_t d1 = q[0][0];
  if (d1 <= 0) return false;
  const int64_t l21 = fx::div_q(q[1][0], d1, kQ), l31 = fx::div_q(q[2][0], d1, kQ);
  const int64_t d2 = q[1][1] - fx::shr_round(fx::shr_round(l21 * l21, kQ) * d1, kQ);
  constexpr int64_t kMinPivot = int64_t{1} << (kQ - 20);  // 1e-6: the prior keeps the pivots far above it
  if (d2 < kMinPivot) return false;
  const int64_t l32 = fx::div_q(q[2][1] - fx::shr_round(fx::shr_round(l31 * l21, kQ) * d1, kQ), d2, kQ);
  const int64_t d3 = q[2][2] - fx::shr_round(fx::shr_round(l31 * l31, kQ) * d1, kQ) -
                     fx::shr_round(fx::shr_round(l32 * l32, kQ) * d2, kQ);
  if (d3 < kMinPivot) return false;
  int64_t w[kMatchParams];
  for (int i = 0; i < kMatchParams; ++i) w[i] = fx::div_q(b_[i], s[i], 0);  // Q20
  w[1] -= fx::shr_round(l21 * w[0], kQ);
  w[2] -= fx::shr_round(l31 * w[0], kQ) + fx::shr_round(l32 * w[1], kQ);
  int64_t y[kMatchParams] = {fx::div_q(w[0], d1, kQ), fx::div_q(w[1], d2, kQ), fx::div_q(w[2], d3, kQ)};
  y[1] -= fx::shr_round(l32 * y[2], kQ);
  y[0] -= fx::shr_round(l21 * y[1] + l31 * y[2], kQ);
  int32_t p[kMatchParams];
  for (int i = 0; i < kMatchParams; ++i) {
    const int64_t pi = fx::div_q(y[i], s[i], kQ);
    if (abs64(pi) > kMaxParamQ30[i]) return false;
    p[i] = static_cast<int32_t>(pi);
  }
  // R^2 = p^T b / z^T z, both Q40 (p >> 10 times b >> 20: < 2^21 * 2^41);
  // the weight it gives, never less than it was (Q16).
  int64_t explained = 0;
  solved_ = true;
  for (int i = 0; i < kMatchParams; ++i) {
    est_[i] = p[i];
    explained += fx::shr_round(p[i], 10) * fx::shr_round(b_[i], 20);
  }
  if (zz_ > 0 && explained > 0) {
    const int64_t r2 = fx::div_q(explained, zz_, 16);
    const int64_t share = fx::div_q((r2 - kExplainedNoneQ16) * 65536, kExplainedSpanQ16, 0);
    const int32_t wc = static_cast<int32_t>(share < 0 ? 0 : (share > 65536 ? 65536 : share));
    if (wc > weight_) weight_ = wc;
  }
  bool changed = false;
  for (int i = 0; i < kMatchParams; ++i) {
    const int32_t applied = static_cast<int32_t>(fx::shr_round(int64_t{p[i]} * weight_, 16));
    changed = changed || applied != p_[i];
    p_[i] = applied;
  }
  return changed;
}

}  // namespace lumavel

#endif  // LUMAVEL_MATCH_FRAMES > 0
