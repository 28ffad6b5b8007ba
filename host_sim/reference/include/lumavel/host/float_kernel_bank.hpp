// The double twin of firmware/core/kernel_bank.hpp (read the core's header
// for the geometry and why): the same tables by the same Simpson rule and
// normalisation, integrated over the exact column edges, unquantised.
#pragma once
#include <Eigen/Dense>
#include <vector>

#include "lumavel/host/float_column_band.hpp"
#include "lumavel/host/settings.hpp"

namespace lumavel::host {

struct FloatCameraKernels {
  Eigen::VectorXd norm, norm_d;          // normaliser window (order 0) and its angular derivative
  Eigen::VectorXd dc;                    // F of a uniform image, per kernel (sum K / sum N)
  double dark_n = 0;                     // the normaliser of a uniform image at kNoLightMeanDn
  std::vector<Eigen::VectorXd> k, d, t;  // B, dB/dtheta, d3B/dtheta3 kernels
  Eigen::VectorXd lean;                  // -d ln(elevation scale)/d(yaw) per column (when leaning)
};

// Tables of both cameras, built exactly as build_kernel_bank does.
struct FloatKernelBank {
  FloatCameraKernels cam[2];
  Eigen::VectorXd edge[2];    // column edge yaws, width + 1
  FloatColumnBand band;       // the rows each column sums, the tables' cos(a_u) weight
  std::vector<double> sigma;  // each kernel's scale, rad (one per kernel: the bank's kernel count)
  bool leaning = false;       // the rotation term's edge-row correction applies (not banded, 2+ rows)
  double axis_offset[2] = {0, 0};  // each camera's axis yaw from the kernels' centre (the core's KernelBank::axis_offset)
};
FloatKernelBank build_float_kernel_bank(const EstimatorSettings& s);

}  // namespace lumavel::host
