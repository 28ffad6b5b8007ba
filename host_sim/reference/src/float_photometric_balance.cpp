#include "lumavel/host/float_photometric_balance.hpp"

#include <algorithm>
#include <cmath>

#include "lumavel/host/float_estimator.hpp"

namespace lumavel::host {

void FloatPhotometricBalance::reset() {
  learned_ = 0;
  mean_s_.setZero();
}

void FloatPhotometricBalance::learn(const FloatMeasurement& a, const FloatMeasurement& b, double dtheta, double d,
                                    double ratio) {
  const double travel = std::fabs(d);
  if (travel == 0 || ratio == 0 || std::fabs(ratio) * params::kBalanceMaxLeadSteps < 1) return;
  if (std::fabs(dtheta) > params::kBalanceMaxCurvature * travel) return;
  const double lead = 1 / ratio;
  const double step = std::min(travel, params::kBalanceLength);
  const double alpha = learned_ < params::kBalanceLength ? step / (learned_ + step) : step / params::kBalanceLength;
  learned_ = std::min(learned_ + step, params::kBalanceLength);
  for (Eigen::Index k = 0; k < b.diff.size(); ++k) {
    const double s_bar = (a.diff[k] + a.balance[k] + b.diff[k] + b.balance[k]) / 2;
    const double dm = (b.mid[k] + b.balance[k] / 2) - (a.mid[k] + a.balance[k] / 2);
    const double r_bar = (a.rot[k] + b.rot[k]) / 2;
    const double e = s_bar - lead * (dm - dtheta * r_bar);
    mean_s_[k] += alpha * (e - mean_s_[k]);
  }
}

}  // namespace lumavel::host
