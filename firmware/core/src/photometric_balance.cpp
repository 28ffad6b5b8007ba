#include "lumavel/core/photometric_balance.hpp"

#include "lumavel/core/measurement.hpp"

namespace lumavel {
namespace {

constexpr int64_t kMaxLeadSteps = fx::q_of(params::kBalanceMaxLeadSteps, 0);
constexpr int64_t kMaxCurvatureQ12 = fx::q_of(params::kBalanceMaxCurvature, 12);

int64_t abs64(int64_t v) { return v < 0 ? -v : v; }

}  // namespace

void PhotometricBalance::reset() {
  learned_q16_ = 0;
  for (int k = 0; k < kMaxKernels; ++k) mean_s_[k] = 0;
}

void PhotometricBalance::learn(const BalanceInput& in) {
  const int64_t travel = abs64(in.displacement);
  const int64_t ratio = abs64(in.distance_ratio);  // |d / h|, Q28
  if (travel == 0 || ratio == 0 || ratio * kMaxLeadSteps < (int64_t{1} << fx::kValueFrac)) return;
  // |dtheta| / d above kBalanceMaxCurvature: Q28 rad against Q12 rad/m x Q16 m.
  if (abs64(in.dtheta) > kMaxCurvatureQ12 * travel) return;
  // h / d = 2^32 / (d/h in Q20) in Q12: one 32-bit division (d/h in Q20 >= 2^14 here, < 2^31 for |d/h| < 8).
  const uint32_t ratio_q20 = static_cast<uint32_t>(fx::sat32(ratio >> 8));
  const int64_t lead_mag = int64_t{0xFFFFFFFFu / ratio_q20};
  const int64_t lead_q12 = in.distance_ratio < 0 ? -lead_mag : lead_mag;
  const int64_t step = travel < kLengthQ16 ? travel : kLengthQ16;
  const int32_t alpha = learned_q16_ < kLengthQ16 ? fx::fraction_q16(step, learned_q16_ + step)
                                                  : fx::fraction_q16(step, kLengthQ16);
  learned_q16_ = learned_q16_ + step < kLengthQ16 ? learned_q16_ + step : kLengthQ16;
  const StereoMeasurement& a = *in.prev;
  const StereoMeasurement& b = *in.cur;
  for (uint8_t k = 0; k < b.count; ++k) {
    // Raw values: the correction subtracted b from F1, i.e. from S, and half of it from M.
    const int64_t s_bar = (int64_t{a.diff[k]} + a.balance[k] + b.diff[k] + b.balance[k]) / 2;
    const int64_t dm = (int64_t{b.mid[k]} + b.balance[k] / 2) - (int64_t{a.mid[k]} + a.balance[k] / 2);
    const int64_t r_bar = fx::shr_round(int64_t{a.rot[k]} + b.rot[k], 1);
    const int64_t innovation = dm - fx::shr_round(int64_t{in.dtheta} * r_bar, fx::kSlopeFrac);
    // The residual of S against the stereo prediction; |innovation| < 2^31, |lead| <= 2^18.
    const int64_t e = s_bar - fx::shr_round(lead_q12 * fx::sat32(innovation), 12);
    mean_s_[k] = fx::sat32(mean_s_[k] + fx::shr_round((e - mean_s_[k]) * alpha, 16));  // |e - b| < 2^40
  }
}

}  // namespace lumavel
