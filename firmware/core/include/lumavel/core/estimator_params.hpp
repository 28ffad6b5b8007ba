// Constants of the differential estimator (the kernel bank, the measurement,
// the observer, the gyro): one source for the firmware core (which builds its
// integer constants from these values at compile time, each named with its
// format) and the double-precision twin (host_sim/reference). Each value says
// what it means physically. (The time of flight and the fusion have theirs in
// fusion_params.hpp, the photometric balance in photometric_params.hpp.)
#pragma once

namespace lumavel::params {

// ---- kernel bank (kernel_bank.hpp) ----
// Simpson intervals per column when a kernel is integrated over a column's
// field of view: error ~1e-7 for kernels at least a column wide. Even.
constexpr int kKernelSimpsonIntervals = 8;
// A kernel is zero beyond this many sigmas from its centre (the Gaussian is
// below 2.3e-11 of its peak there; the core's Hermite recursion is sized for it).
constexpr double kKernelCutoffSigma = 7.0;

// ---- column profile (column_profile.hpp) ----
// One row in this many is checked for clipped (0 or 255) pixels: the
// saturation flag needs a fraction, not every pixel.
constexpr int kClipRowStep = 8;

// ---- measurement (measurement.hpp) ----
// No light: the normaliser below that of a uniform image this bright (DN of
// 255). A black frame is the sensor's noise clipped at 0 (lights off, a lens
// cap: mean 0.6 DN, 63 % of the pixels at 0 with 1.5 DN of noise); divided by
// its own N, that noise reads as texture far above the low-texture threshold
// and as wild velocities (the dark-frames study: V went from 1 to -0.27 m/s
// through 1.2 s of darkness). A dim scene is brighter than this; a camera with
// a black-level offset shows darkness above it (low signal, not caught here).
constexpr int kNoLightMeanDn = 2;

// Each kernel's local spatial frequency w, as (sigma w)^2, is clamped to this
// band, the one a Gaussian-derivative kernel passes: continuous, so that noise
// near w^2 = 0 cannot switch the finite-baseline correction on and off.
constexpr double kSigmaW2Min = 0.09;
constexpr double kSigmaW2Max = 16.0;

// ---- velocity observer (velocity_observer.hpp) ----
// The finite-baseline correction x / tan(x) takes half the phase difference
// between the cameras, x = k h / 2 (rad), clamped to this (x / tan x = 0.47
// there, and 0 at pi / 2: a kernel would be silenced by one noisy phase). The
// core's series for x / tan x is accurate to 3e-5 up to this bound.
constexpr double kMaxHalfPhase = 1.2;
// The estimate is flagged converging until the observer has run this many
// time constants (tau) since it started.
constexpr double kConvergingTaus = 3.0;
// After a (re)start the observer averages the direct values that came since,
// the first one weighed as if it stood for this many time constants of them
// (0: their plain mean; 1: the first value decayed from for tau). A start is
// one noisy value, but so are the few after it: a plain mean chased the
// biased first values of mismatched cameras among near clutter (+12 % E), a
// whole tau lagged every start (the wide-lens slalom 2.10 against 1.81 %;
// docs/design.md).
constexpr double kObserverStartPrior = 0.25;

// ---- estimator (estimator.hpp) ----
// A frame interval longer than this many frame periods is flagged a frame gap
// (a dropped frame; a longer one than max_gap restarts the observer).
constexpr double kFrameGapPeriods = 1.5;

// ---- gyro (gyro_integrator.hpp, gyro_offset.hpp) ----
// Longest interval over which one rate is integrated (s): between two samples
// and beyond the last one, a longer hole adds no more rotation (the core's
// 64-bit trapezoid also needs it below 2^64 / 2^32 ns = 4.29 s).
constexpr double kGyroMaxStep = 4.0;
// A still period longer than this (s) renews the offset's reference (the
// offset learned so far is kept), so that the offset follows drift.
constexpr double kGyroOffsetRenewal = 20.0;
// Each camera's own change since the stillness reference may read up to this
// many still distances (the stereo mean's, up to one): one camera is noisier
// than the mean of two, and at one the day soak's two engines judged a still
// start differently on 9 frames (a reading on the bound). Real motion passes
// any such bound within frames; the stripes it is for move 16 mm a frame.
constexpr double kStillCameraFactor = 2.0;

}  // namespace lumavel::params
