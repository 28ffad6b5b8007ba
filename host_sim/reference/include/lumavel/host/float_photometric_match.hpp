// The double twin of firmware/core/photometric_match.hpp (read the core's
// header for the model, the samples and why): cam1's column sums mapped onto
// cam0's with (a1, a2, beta), learned where the trailing camera stands where
// the leading one stood.
#pragma once
#include <Eigen/Dense>
#include <cstdint>
#include <deque>

#include "lumavel/core/limits.hpp"
#include "lumavel/host/float_column_profile.hpp"
#include "lumavel/host/float_kernel_bank.hpp"

namespace lumavel::host {

class FloatPhotometricMatch {
 public:
  static constexpr int kParams = 3;
  using Params = Eigen::Matrix<double, kParams, 1>;
  // cam1's profile mapped with the current p (rows: each column's row count).
  FloatColumnProfile apply(const FloatColumnProfile& p1, const Eigen::VectorXd& rows) const;
  // cam1's dF/dp (kernels x 3) from the mapped profile and its outputs f1.
  Eigen::MatrixXd jacobian(const FloatColumnProfile& p1, const Eigen::VectorXd& rows, const FloatCameraKernels& ck,
                           const Eigen::VectorXd& f1) const;
  struct Input {
    uint64_t t_ns;
    double heading;              // rad
    const Eigen::VectorXd* f[2];  // each camera's F (cam1's with the current p)
    const Eigen::VectorXd* r[2];  // each camera's dF/dtheta
    const Eigen::MatrixXd* jac;  // cam1's dF/dp
    double v;                    // the fused V, m/s
    double baseline;             // h, m
    double max_rotation;         // rad
    bool usable;
  };
  // One frame; true when p changed (delta(): the change).
  bool learn(const Input& in);
  const Params& params() const { return p_; }
  Params delta() const { return p_ - p_before_; }

 private:
  struct Frame {
    uint64_t t_ns;
    double heading;
    Eigen::VectorXd f[2], r[2];  // cam1's F linearised: F1 - J p
    Eigen::MatrixXd jac;
  };
  void sample(size_t fixed, int fixed_cam, double t_other, int lead, double max_rotation);
  bool solve();

  Params p_ = Params::Zero(), p_before_ = Params::Zero();  // applied
  Params est_ = Params::Zero();  // the solution; p_ is weight_ of it
  double weight_ = 0;            // from R^2, never lowered
  std::deque<Frame> hist_;
  Eigen::Matrix<double, kParams, kParams> a_ = Eigen::Matrix<double, kParams, kParams>::Zero();
  Params b_ = Params::Zero();
  double ee_ = 0, zz_ = 0, dof_ = 0, ee_rows_ = 0;  // ee_ and its rows: after a solution only
  bool solved_ = false;
  int samples_ = 0, unsolved_ = 0;
};

}  // namespace lumavel::host
