// Two cameras that are not photometric twins, mapped onto each other.
//
// What differs between two cheap cameras of one model, and reads as velocity
// through S = F1 - F0: the black level (a constant per pixel), the
// vignetting (a smooth fall-off that differs by several percent between two
// lenses), a tilt of it (an off-centre lens), the gain (cancelled by the
// division by N). cam1's column sums are mapped onto cam0's with three
// parameters, p = (a1, a2, beta):
//   sum'(u) = (sum(u) - rows(u) beta) (1 + a1 x_u + a2 x_u^2)
//             + a2 (sum_y2(u) - rows_y2 beta),
// x_u in (-1, 1) the column's centre across the image, sum_y2 the column
// summed with weight y^2 (column_profile.hpp; without a band): the
// vignetting is radial, a2 (x^2 + y^2) per pixel, and its rows' share in a
// column sum depends on the scene's vertical layout. Linear in each of
// them, so that the Jacobian of cam1's F over p is three more dot products
// per kernel (jacobian()).
//
// Learned where it is exact whatever the depth: moving along the baseline,
// the trailing camera stands where the leading one stood tau = h / |V|
// earlier (the time of flight's principle), so with equal responses
// F_trail(t) = F_lead(t - tau), rotated by the gyro's angle over tau. Each
// frame gives two such samples from a short history, one with the lead
// interpolated in time and one with the trail interpolated (their
// second-order interpolation errors have opposite signs); the direction the
// interpolated side moved over its frame is projected out of each sample,
// so that an error of tau (V is the fused estimate) teaches nothing. The
// samples' normal equations (forgotten over 2^kMatchMemoryLog2 samples) are
// solved every kMatchSolveSamples samples with a prior on p (cameras of one
// model differ by about the kMatchPrior* widths), weighted by the samples'
// own residual variance: about the solution before them (out of sample), the
// samples' whole variance for the first solution. (Counting the samples that
// came before any solution, whose residual is the cameras' whole difference,
// kept the prior strong for seconds: a 3.5 DN black level took 1.5 s.) The
// solution is applied in the measure that it explains the samples (R^2 from
// kMatchExplainedNone to kMatchExplainedAll, never less than it once was):
// twins' samples hold what the sampling itself
// gets wrong, a few tenths of them at most, which a mapping must not chase.
// New parameters change cam1's F: the estimator moves the previous frame's
// F1 by J dp so that the next interval sees no step (estimator.cpp).
//
// Formats: a1, a2 in Q30; beta in units of kMatchOffsetUnit DN, Q30 (so
// that the three columns of J have like sizes); J in Q28 per unit of
// parameter; the normal equations in Q40 (J and the samples in Q20, |J| <= 4
// held, 2^kMatchMemoryLog2 samples of at most kMaxKernels rows: < 2^61).
#pragma once
#include <cstdint>

#include "lumavel/core/column_profile.hpp"
#include "lumavel/core/fixed.hpp"
#include "lumavel/core/kernel_bank.hpp"
#include "lumavel/core/kernel_dot.hpp"
#include "lumavel/core/limits.hpp"
#include "lumavel/core/photometric_params.hpp"

namespace lumavel {

constexpr int kMatchParams = 3;
using MatchJac = ValueQ28[kMaxKernels][kMatchParams];

struct MatchInput {
  uint64_t t_ns;
  int64_t heading;            // offset-corrected gyro integral, unwrapped, Q28 rad
  const ValueQ28* f[2];       // each camera's F (cam1's with the current p)
  const SlopeQ20* r[2];       // each camera's dF/dtheta
  const MatchJac* jac;        // cam1's dF/dp at the current p
  uint8_t count;              // kernels
  SpeedQ16 v;                 // the fused V
  LengthQ24 baseline;         // h (signed: x of cam1 minus x of cam0)
  AngleQ28 max_rotation;      // rotation allowed between the two sightings
  bool usable;                // a clean interval (no gap, no saturation, V measured)
};

class PhotometricMatch {
 public:
  void reset();
  // cam1's profile mapped with the current p, in place (radial: its radial
  // sums, or nullptr: the columns' own share of the vignetting only).
  void apply(ColumnProfile& p1, const ColumnBand* band, uint16_t height, const RadialSums* radial);
  // cam1's dF/dp from the profile apply() gave and its outputs f1 (to first
  // order: d sum'/d a_j taken as sum' x^j, not sum' x^j / (1 + a1 x + a2 x^2);
  // an error of J slows the learning, it does not move where it ends). The
  // black level's column does not depend on the image: its dot products are
  // kept until p or the geometry changes (reset() on a new configuration).
  // norm1: cam1's normaliser as the measurement took it from this profile
  // (stereo_measurement), the same N without its dot product and division
  // again; nullptr: taken here.
  void jacobian(const ColumnProfile& p1, const ColumnBand* band, uint16_t height, const RadialSums* radial,
                const CameraKernels& ck, uint8_t count, const ValueQ28* f1, MatchJac& jac,
                const kdot::Normaliser* norm1 = nullptr);
  // One frame; true when p changed (by delta(), Q30 per parameter).
  bool learn(const MatchInput& in);
  const int32_t* params() const { return p_; }
  // A known mapping (Q30 each), as learn() would have left it.
  void set_params(const int32_t* p_q30) {
    for (int j = 0; j < kMatchParams; ++j) p_[j] = p_before_[j] = est_[j] = p_q30[j];
    weight_ = 1 << 16;
    solved_ = true;
  }
  int32_t delta(int j) const { return p_[j] - p_before_[j]; }

 private:
  struct Frame {
    uint64_t t_ns;
    int64_t heading;
    ValueQ28 f[2][kMaxKernels];  // cam1's linearised: F1 - J p (the p it was taken with removed)
    SlopeQ20 r[2][kMaxKernels];
    ValueQ28 jac[kMaxKernels][kMatchParams];
  };
  void sample(int fixed, int fixed_cam, uint64_t t_other, int lead, uint8_t count, AngleQ28 max_rotation);
  bool solve();

  int32_t p_[kMatchParams] = {};         // Q30, applied
  int32_t p_before_[kMatchParams] = {};  // before the last learn()
  Frame hist_[kMatchFrames > 0 ? kMatchFrames : 1];
  int n_hist_ = 0, head_ = 0;            // ring: head_ the oldest
  int64_t a_[kMatchParams][kMatchParams] = {};  // sum J'^T J', Q40 (symmetric: the lower triangle kept)
  int64_t b_[kMatchParams] = {};         // sum J'^T z', Q40
  int64_t ee_ = 0;                       // sum of squared prediction residuals (after a solution), Q40
  int64_t zz_ = 0;                       // sum of squared samples, Q40
  int32_t est_[kMatchParams] = {};       // the solution; p_ is weight_ of it
  int32_t weight_ = 0;                   // Q16, from R^2, never lowered
  int64_t dof_ = 0;                      // rows in those sums
  int64_t ee_rows_ = 0;                  // rows in ee_
  bool solved_ = false;                  // est_ holds a solution
  int32_t samples_ = 0;                  // held at kMatchMemorySamples
  int32_t unsolved_ = 0;                 // samples since the last solution
  struct BetaDots {                      // the black level's dot products, for this p and geometry
    bool valid;
    bool q8;
    uint8_t count;
    uint16_t width, height;
    int32_t p[kMatchParams];
    bool radial;
    int32_t rows_y2;
    int64_t norm;
    int64_t k[kMaxKernels];
  };
  BetaDots beta_dots_ = {};
};

}  // namespace lumavel
