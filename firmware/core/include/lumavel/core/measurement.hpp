// Per-frame stereo measurement: the normalised kernel outputs of both
// cameras combined into mid values, the baseline difference and the
// rotation derivative (paper eq. 2, 6, 8, 21).
#pragma once
#include <cstdint>

#include "lumavel/core/column_profile.hpp"
#include "lumavel/core/fixed.hpp"
#include "lumavel/core/kernel_bank.hpp"

namespace lumavel {

struct StereoMeasurement {
  uint8_t count;
  ValueQ28 mid[kMaxKernels];    // M = (F0 + F1) / 2, F = B / N (eq. 21 normalisation)
  ValueQ28 diff[kMaxKernels];   // S = F1 - F0 = h dF/dx (eq. 8, misalignment in the kernels)
  SlopeQ20 rot[kMaxKernels];    // R = (dF0/dtheta + dF1/dtheta) / 2 per radian
  CurvQ12 curv[kMaxKernels];    // C = mean d3B/dtheta3 / N per radian^3 (derivatives of N neglected)
  bool no_light;                // a normaliser was zero
  bool saturated;               // a ratio saturated
  uint32_t clipped;             // clipped pixels in both frames
};

// From the two column profiles and the bank.
void stereo_measurement(const ColumnProfile& p0, const ColumnProfile& p1, const KernelBank& bank,
                        StereoMeasurement& out);

}  // namespace lumavel
