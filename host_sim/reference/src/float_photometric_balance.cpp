// Twin of firmware/core/src/photometric_balance.cpp.
#include "lumavel/host/float_photometric_balance.hpp"

#include <algorithm>
#include <cmath>

#include "lumavel/host/float_measurement.hpp"

namespace lumavel::host {

void FloatPhotometricBalance::reset() {
  learned_ = 0;
  mean_s_.setZero();
}

void FloatPhotometricBalance::learn(const FloatStereoMeasurement& a, const FloatStereoMeasurement& b, double dtheta,
                                    double h) {
  const Eigen::Index n = b.diff.size();
  Eigen::VectorXd s_bar(n), innovation(n), s_corr(n);
  for (Eigen::Index k = 0; k < n; ++k) {
    // Held within +-2, as the core holds them.
    s_bar[k] = std::clamp((a.diff[k] + a.balance[k] + b.diff[k] + b.balance[k]) / 2, -2.0, 2.0);
    const double dm = (b.mid[k] + b.balance[k] / 2) - (a.mid[k] + a.balance[k] / 2);
    innovation[k] = std::clamp(dm - dtheta * (a.rot[k] + b.rot[k]) / 2, -2.0, 2.0);
    s_corr[k] = std::clamp((a.diff[k] + b.diff[k]) / 2, -2.0, 2.0);
  }
  const double den = s_corr.squaredNorm(), num = innovation.dot(s_corr);
  if (den <= 0 || num == 0) return;
  const double ratio = num / den;
  const double ratio_abs = std::fabs(ratio), travel = ratio_abs * std::fabs(h);
  const double ratio_min = 1 / (2 * params::kBalanceMaxLeadSteps);
  if (ratio_abs <= ratio_min || travel == 0) return;
  const double w_lead = std::min(ratio_abs - ratio_min, ratio_min) / ratio_min;
  const double lim = params::kBalanceMaxCurvature * travel, turn = std::fabs(dtheta);
  if (turn >= lim) return;
  const double w_turn = std::min(lim - turn, lim / 2) / (lim / 2);
  const double step = std::min(travel * w_lead * w_turn, params::kBalanceLength);
  if (step == 0) return;
  const double alpha = learned_ < params::kBalanceLength ? step / (learned_ + step) : step / params::kBalanceLength;
  learned_ = std::min(learned_ + step, params::kBalanceLength);
  mean_s_ += alpha * ((s_bar - innovation / ratio) - mean_s_);
}

}  // namespace lumavel::host
