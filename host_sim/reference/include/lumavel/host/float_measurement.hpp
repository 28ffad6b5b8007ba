// The double twin of firmware/core/measurement.hpp: both cameras' normalised
// kernel outputs combined into the mid values, the baseline difference, the
// rotation derivative and each kernel's half phase (paper eq. 2, 6, 8, 21).
#pragma once
#include <Eigen/Dense>

#include "lumavel/host/float_column_profile.hpp"
#include "lumavel/host/float_kernel_bank.hpp"
#include "lumavel/host/float_photometric_balance.hpp"

namespace lumavel::host {

struct FloatStereoMeasurement {
  Eigen::VectorXd mid, diff, rot;  // M = (F0 + F1) / 2, S = F1 - F0, R = mean dF/dtheta
  Eigen::VectorXd half_phase;      // x = k h / 2 per kernel, from the cameras' phases
  Eigen::VectorXd f[2], r[2];      // each camera's F and dF/dtheta
  Eigen::VectorXd balance;         // the photometric offset subtracted from cam1's F
  bool no_light = false;           // a normaliser was not positive
  double clipped = 0;              // clipped pixels in both frames
};

// From the two column profiles and the bank; with a balance, cam1's outputs
// are corrected by it first (nullptr: the cameras taken as twins).
FloatStereoMeasurement float_stereo_measurement(const FloatColumnProfile& p0, const FloatColumnProfile& p1,
                                                const FloatKernelBank& bank,
                                                const FloatPhotometricBalance* balance = nullptr);

}  // namespace lumavel::host
