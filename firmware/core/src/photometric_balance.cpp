#include "lumavel/core/photometric_balance.hpp"

#include "lumavel/core/measurement.hpp"

namespace lumavel {
namespace {

constexpr int64_t kMaxLeadSteps = fx::q_of(params::kBalanceMaxLeadSteps, 0);
constexpr int64_t kInvLengthQ36 = fx::q_of(1.0 / params::kBalanceLength, 36);
constexpr int64_t kMaxCurvatureQ20 = fx::q_of(params::kBalanceMaxCurvature, 20);  // 4e-6 of itself

int64_t abs64(int64_t v) { return v < 0 ? -v : v; }

// Held within +-2 (Q28): S and dM are far below it on any usable frame.
int32_t clamp2(int64_t v) {
  constexpr int64_t kLim = int64_t{2} << fx::kValueFrac;
  return static_cast<int32_t>(v > kLim ? kLim : (v < -kLim ? -kLim : v));
}

}  // namespace

void PhotometricBalance::reset() {
  learned_q24_ = 0;
  for (int k = 0; k < kMaxKernels; ++k) mean_s_[k] = 0;
}

void PhotometricBalance::learn(const BalanceInput& in) {
  const StereoMeasurement& a = *in.prev;
  const StereoMeasurement& b = *in.cur;
  // Raw S and dM (the correction subtracted b_k from F1, i.e. from S, and
  // half of it from M), and the interval's distance d / h by least squares
  // on S as corrected (the raw S carries b_k: d would absorb its part along S).
  int32_t s_bar[kMaxKernels], innovation[kMaxKernels];
  int64_t num = 0, den = 0;  // Q56: full precision (a Q28 sum keeps 4 digits of a weak texture's S^2)
  for (uint8_t k = 0; k < b.count; ++k) {
    s_bar[k] = clamp2((int64_t{a.diff[k]} + a.balance[k] + b.diff[k] + b.balance[k]) / 2);
    const int64_t dm = (int64_t{b.mid[k]} + b.balance[k] / 2) - (int64_t{a.mid[k]} + a.balance[k] / 2);
    const int64_t r_bar = fx::shr_round(int64_t{a.rot[k]} + b.rot[k], 1);
    innovation[k] = clamp2(dm - fx::shr_round(int64_t{in.dtheta} * r_bar, fx::kSlopeFrac));
    const int64_t s_corr = clamp2((int64_t{a.diff[k]} + b.diff[k]) / 2);
    num += int64_t{innovation[k]} * s_corr;  // |.| <= 2^58 each, 6 kernels < 2^61
    den += s_corr * s_corr;
  }
  if (den <= 0 || num == 0) return;
  // |d| = |d / h| |h| (Q28 x Q24 >> 28: Q24 m).
  const int64_t ratio = abs64(fx::div_q(num, den, fx::kValueFrac));
  const int64_t travel = (ratio * abs64(in.baseline)) >> 28;
  // Weights that fade in continuously (a hard gate would let the twin, a
  // rounding away, take a different sample): the lead h / d from
  // 2 kBalanceMaxLeadSteps down to kBalanceMaxLeadSteps, the curvature
  // |dtheta| / d from kBalanceMaxCurvature down to half of it.
  constexpr int64_t kRatioMinQ28 = (int64_t{1} << fx::kValueFrac) / (2 * kMaxLeadSteps);
  if (ratio <= kRatioMinQ28 || travel == 0) return;
  const int64_t over = ratio - kRatioMinQ28;
  const int64_t w_lead = fx::fraction_q16(over < kRatioMinQ28 ? over : kRatioMinQ28, kRatioMinQ28);
  const int64_t lim = kMaxCurvatureQ20 * travel;  // Q44 rad: Q20 rad/m x Q24 m (< 2^47)
  const int64_t turn = abs64(in.dtheta) << 16;    // Q28 -> Q44
  if (turn >= lim) return;
  const int64_t straight = lim - turn;
  const int64_t w_turn = fx::fraction_q16(straight < lim / 2 ? straight : lim / 2, lim / 2);
  const int64_t step = fx::shr_round(fx::shr_round(travel * w_lead, 16) * w_turn, 16);
  if (step == 0) return;
  // The lead h / d = den / num in Q20 (|.| <= 2 kBalanceMaxLeadSteps here): a
  // coarser one would leave its rounding times S in every sample.
  const int64_t lead_q20 = fx::div_q(den, num, 20);
  // alpha in Q30 (in Q16 a step of a few mm would be rounded by several per
  // cent: a weight the twin does not give); after the running mean, a
  // multiply by the constant 1 / kBalanceLength.
  const int64_t capped = step < kLengthQ24 ? step : kLengthQ24;
  const int64_t alpha = learned_q24_ < kLengthQ24 ? fx::div_q(capped, learned_q24_ + capped, 30)
                                                  : (capped * kInvLengthQ36) >> 30;  // < 2^26 x 2^36
  learned_q24_ = learned_q24_ + capped < kLengthQ24 ? learned_q24_ + capped : kLengthQ24;
  for (uint8_t k = 0; k < b.count; ++k) {
    // The residual of S against the stereo prediction; |innovation| <= 2^29, |lead| <= 2^25.
    const int64_t e = s_bar[k] - fx::shr_round(lead_q20 * innovation[k], 20);
    const int64_t de = fx::sat32(e) - int64_t{mean_s_[k]};  // |.| < 2^32
    mean_s_[k] = fx::sat32(mean_s_[k] + fx::shr_round(de * alpha, 30));
  }
}

}  // namespace lumavel
