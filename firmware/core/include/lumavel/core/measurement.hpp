// Per-frame stereo measurement: the normalised kernel outputs of both
// cameras combined into mid values, the baseline difference and the
// rotation derivative (paper eq. 2, 6, 8, 21).
//
// The rotation derivative and the column edges. A pinhole column at yaw a
// from the axis sums its rows over |tan E| <= (H/2) s / f, s = cos a (a lens:
// its elevation scale), and its sum carries a factor f / s. Turning the
// camera slides the scene through the columns, but not rigidly: each column
// keeps its own elevation extent and factor. By Leibniz' rule the true
// rotation derivative of a column sum P is the derivative along the columns
// (the D tables) plus lean (E), lean = -d ln s / d(yaw) (the bank's, tan a for
// a pinhole) and E = (H/2)(edge rows' value at the image's edge) - P; with all
// rows of a uniform column E = 0. Through the B kernels it adds sum_u K[u]
// lean[u] E[u] to dB/dtheta (and to dN/dtheta). Without it a wide camera
// turning reads as motion (the slalom of docs/results.md at hfov 90: E 12 %
// -> 4 %); with the elevation band (every column the same extent) it is not
// needed and not applied, nor on a line scan (one row, E = 0).
//
// The same lean on a misaligned rig. Both cameras' kernels are centred on one
// body yaw, which takes the misalignment out of the shift exactly, but a
// camera turned by m from the centre still sees each body yaw through a
// column of its own elevation reach and factor: its B is the centred one
// plus m sum_u K[u] lean[u] E[u], which reads as stereo where h/Z is of m's
// size (a photo wall at 4 m, 1.6 deg: E 19 %). So each camera's F is taken
// back to the centre axis to first order, F - m (C_k - F C_N) / N with C the
// same edge-row dot products (KernelBank::axis_offset is m; docs/design.md,
// "Misalignment").
#pragma once
#include <cstdint>

#include "lumavel/core/column_profile.hpp"
#include "lumavel/core/fixed.hpp"
#include "lumavel/core/kernel_bank.hpp"
#include "lumavel/core/kernel_dot.hpp"
#include "lumavel/core/photometric_balance.hpp"

namespace lumavel {

struct StereoMeasurement {
  uint8_t count;
  ValueQ28 mid[kMaxKernels];    // M = (F0 + F1) / 2, F = B / N (eq. 21 normalisation)
  ValueQ28 diff[kMaxKernels];   // S = F1 - F0 = h dF/dx (eq. 8, misalignment in the kernels)
  SlopeQ20 rot[kMaxKernels];    // R = (dF0/dtheta + dF1/dtheta) / 2 per radian
  // Each kernel's output read as a local sinusoid of angular frequency w:
  // w^2 = -C R / R^2 (C = d3F/dtheta3, derivatives of N neglected) and
  // z_i = (F_i - dc) - i R_i / w; half_phase = arg(z1 conj(z0)) / 2 = k h / 2.
  AngleQ28 half_phase[kMaxKernels];
  ValueQ28 f[2][kMaxKernels];   // each camera's F (the time of flight compares cam0 with cam1's past)
  SlopeQ20 r[2][kMaxKernels];   // each camera's dF/dtheta
  ValueQ28 balance[kMaxKernels];  // the photometric offset subtracted from cam1's F (photometric_balance.hpp)
  bool no_light;                // a normaliser was zero
  bool saturated;               // a ratio saturated
  uint32_t clipped;             // clipped pixels in both frames
};

// From the two column profiles and the bank; with a balance, cam1's outputs
// are corrected by it first (nullptr: the cameras taken as twins). norm1, if
// given, receives cam1's normaliser (the photometric match's Jacobian divides
// by the same N: PhotometricMatch::jacobian).
void stereo_measurement(const ColumnProfile& p0, const ColumnProfile& p1, const KernelBank& bank,
                        const PhotometricBalance* balance, StereoMeasurement& out,
                        kdot::Normaliser* norm1 = nullptr);

}  // namespace lumavel
