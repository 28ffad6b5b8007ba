// The twin of photometric_balance.hpp in double precision: cam1's offset per
// kernel against cam0, the mean over travel of the residual of S against the
// stereo prediction.
#pragma once
#include <Eigen/Dense>

#include "lumavel/core/photometric_params.hpp"

namespace lumavel::host {

struct FloatStereoMeasurement;

class FloatPhotometricBalance {
 public:
  explicit FloatPhotometricBalance(int kernels = 0) : mean_s_(Eigen::VectorXd::Zero(kernels)) {}
  void reset();
  // One usable interval: dtheta the gyro angle, h the baseline.
  void learn(const FloatStereoMeasurement& prev, const FloatStereoMeasurement& cur, double dtheta, double h);
  // cam1's offset b_k; 0 until ready().
  double offset(Eigen::Index k) const { return ready() ? mean_s_[k] : 0; }
  bool ready() const { return learned_ >= params::kBalanceReadyLength; }

 private:
  double learned_ = 0;
  Eigen::VectorXd mean_s_;
};

}  // namespace lumavel::host
