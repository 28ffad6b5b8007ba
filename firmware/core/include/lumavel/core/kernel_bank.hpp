// Kernel tables: for each camera and kernel, the weights that turn a column
// profile into B (the kernel-weighted brightness, paper eq. 2) and into
// dB/dtheta (the derivative kernel, paper eq. 6).
//
// Geometry: kernel k is phi_k(psi - c), a Gaussian derivative of order n_k
// and scale sigma_k in body-frame yaw psi, centred on c = the mean of the two
// optical-axis yaws. A pinhole column is a meridian: all its pixels share one
// body yaw a_u (from the axis). Its row y sees elevation E with
// tan E = y cos(a_u) / f, so a column's sum over rows |y| <= b is
// f / cos(a_u) * Int I(psi, E) d(tan E) over |tan E| <= b cos(a_u) / f. Two
// things in it are fixed to the camera, not to the scene, and break the
// rotation identity on wide cameras: the factor 1 / cos(a_u) and the band
// edge. So every column sums only the elevation band that all columns see
// (b_u = (H/2) cos(a_min) / cos(a_u), fractional rows at its edges: the
// ColumnBand, one for both cameras with their cos(a_u) averaged), and every
// table is weighted by cos(a_u): then B is an integral of the scene alone,
// for any texture, and moves rigidly with it. Through a lens, cos(a_u) is
// the host's elevation scale of the column (EstimatorConfig::elevation_scale:
// f d(tan E)/d(row) over the band, which a pinhole's cos(a_u) is).
// Each table integrates phi over the true yaw interval of each column
// (pinhole edges, atan), so that edge columns, which span less yaw than
// central ones, weigh less:
//     K[u] =  cos(a_u) Int_{column u} phi(psi - c) dpsi
//     D[u] = -cos(a_u) Int_{column u} phi'(psi - c) dpsi   = cos(a_u) (phi(start) - phi(end))
//     T[u] = -cos(a_u) Int_{column u} phi'''(psi - c) dpsi
// (cos(a_u) = 1 when the bank is not banded).
// D is then the exact rotation derivative of B for a piecewise-constant profile.
// (The cos weight alone, over full columns, was tried first: it broke the
// identity by 5-13 % on odd kernels, because the band edge still moved.)
// Centring both cameras on the same body yaw compensates the misalignment
// exactly (paper eq. 8 does it to first order).
//
// Storage: q31_t, value = w * 2^-(31 + exp). Each table uses the full range
// (|w| max in [2^30, 2^31)), so table rounding is <= 2^-31 of the peak:
// below 1e-9 relative, 4 orders under the 0.1 % fixed-vs-float budget.
#pragma once
#include <cstdint>

#include "lumavel/core/column_profile.hpp"
#include "lumavel/core/config.hpp"
#include "lumavel/core/fixed.hpp"
#include "lumavel/core/limits.hpp"

namespace lumavel {

struct KernelTable {
  q31_t w[kMaxColumns];
  int8_t exp;  // value = w * 2^-(31 + exp)
};

// The third-derivative tables only set each kernel's local frequency for the
// finite-baseline correction (measurement.hpp): 1e-4 relative is plenty, so
// they are kept in 16 bits (2^-15 of the peak), half the RAM of a q31 table.
struct KernelTable16 {
  int16_t w[kMaxColumns];
  int8_t exp;  // value = w * 2^-(15 + exp)
};

struct CameraKernels {
  KernelTable norm;                 // normaliser window (order 0)
  KernelTable norm_d;               // its angular derivative
  KernelTable k[kMaxKernels];       // B kernels
  KernelTable d[kMaxKernels];       // dB/dtheta kernels
  KernelTable16 t[kMaxKernels];     // d3B/dtheta3 kernels (finite-baseline correction)
  int64_t dark_n;                   // the normaliser of a uniform image at kNoLightMeanDn, in q8 sums
};

struct KernelBank {
  uint16_t width;
  uint8_t count;
  bool banded;      // false: every column sums all rows (line scans, bands under 2 rows)
  ColumnBand band;  // both cameras', when banded
  const ColumnBand* column_band() const { return banded ? &band : nullptr; }
  // The rows' rings for a radial weighting (column_profile.hpp), where the
  // columns sum all rows (more than one row, no band).
  RadialRings rings;
  const RadialRings* radial_rings() const { return banded || kBandColumns == 1 || rings.height < 2 ? nullptr : &rings; }
  CameraKernels cam[2];
  ValueQ28 dc[2][kMaxKernels];  // F of a uniform image (sum K / sum N), per camera
  AngleQ28 sigma[kMaxKernels];
  // Each column's lean, -d ln(elevation scale)/d(yaw), per camera, for the
  // rotation term's edge-row correction (measurement.hpp); used where the
  // columns sum all rows (not banded; a line scan keeps one entry, unused).
  bool leaning;
  LeanQ24 lean[2][kBandColumns];
  // Each camera's axis yaw from the kernels' centre c (+-m/2 for a rig
  // misaligned by m): where the columns lean, the first-order correction of
  // the elevation reach that the centring leaves (measurement.hpp).
  AngleQ28 axis_offset[2];
  // No edge table: the edges (column_edge_yaws) are computed while the
  // tables are built, which saves 2 x (kMaxColumns + 1) x 4 bytes of RAM.
};

// Pinhole column edges: axis + u_sign * atan((u - 0.5 - cu) / fu), u = 0..width.
void pinhole_column_edges(const CameraGeometry& g, uint16_t width, AngleQ28* edges);

// The edges the kernels use: pinhole edges plus the lens table
// (EstimatorConfig::edge_offsets, Q15 -> Q28) when there is one. The sum is
// not clamped: validate() refuses tables that leave [-pi, pi] (|pinhole| < 2 pi
// and |offset| < 1 rad keep it far inside int32).
void column_edge_yaws(const CameraGeometry& g, const EdgeOffsetQ15* offsets, uint16_t width, AngleQ28* edges);

// Builds all tables of a validated configuration (cfg.edge_offsets are read
// here and not kept).
void build_kernel_bank(const EstimatorConfig& cfg, KernelBank& bank);

// Gaussian-derivative kernel helpers (exposed for tests).
// phi_n(s) = (-1)^n He_n(s) exp(-s^2/2), s = (psi - c)/sigma, in Q1.30.
int32_t gaussian_derivative_q30(int order, int32_t s_q24);

}  // namespace lumavel
