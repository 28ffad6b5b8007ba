// Parameters of the photometric balance (photometric_balance.hpp): one source
// for the firmware core (integer constants built from these at compile time)
// and the double-precision twin. None is tuned to one recording.
#pragma once

namespace lumavel::params {

// Travel over which the balance is averaged (m): a running mean until this
// much has been seen, an exponential average in travel after. The correction
// is applied after kBalanceReadyLength; before, the two cameras are taken as
// they are. (A slope on M_k as well hurt near clutter and reversals by up to
// 10 points: docs/design.md.)
constexpr double kBalanceLength = 4.0;
// The correction is applied from this much travel on (m): from then the
// least squares that weighs each sample sees the offset removed. (1 m hurt
// near clutter and reversals by 18-26 %, 4 m left the offset half learned on
// a 10 s run; 2 m: docs/design.md.)
constexpr double kBalanceReadyLength = 2.0;
// A frame's weight fades from full at a displacement of |h| / kBalanceMaxLeadSteps
// to nothing at half of it (the stereo prediction h dM / d would amplify the
// noise of dM beyond this).
constexpr double kBalanceMaxLeadSteps = 16.0;
// Frames that turn more than this per metre teach nothing, and the weight
// fades from half of it (rad/m): the
// rotation term of the stereo prediction is first order only, and its error
// (the field of view's, see velocity_observer.hpp) would read as cam1's offset.
constexpr double kBalanceMaxCurvature = 0.05;

// ---- photometric match (photometric_match.hpp) ----
// The match learns from frames where the fused |V| is at least this (m/s):
// slower, tau = h / |V| runs beyond its history (kMatchFrames frames).
constexpr double kMatchMinSpeed = 0.1;
// p is solved from this many samples on (before, cam1 is taken as it is) ...
constexpr int kMatchFirstSamples = 16;
// ... and again after every kMatchSolveSamples new ones (each solution
// moves cam1's F, and costs the M3 about 5000 instructions) ...
constexpr int kMatchSolveSamples = 8;
// ... and the samples are forgotten over this many (a power of two: the
// forgetting is a shift); at 60 Hz, about a minute of travel.
constexpr int kMatchMemoryLog2 = 12;
// The prior: two cameras of one model differ by about this much in each
// parameter (tilt a1, vignetting a2, black level in DN).
constexpr double kMatchPriorTilt = 0.05;
constexpr double kMatchPriorVignetting = 0.1;
constexpr double kMatchPriorOffsetDn = 4.0;
// Consecutive samples share much of their errors (the same scene, one
// history): against the prior, the samples' residual variance counts this
// many times (1, 4, 8, 64 measured: the matched scenes alike, the
// mismatched ones learn later the larger it is; docs/design.md).
constexpr double kMatchSampleCorrelation = 4.0;
// The mapping is applied in the measure that its solution explains the
// samples (R^2 of the fit): not at all up to kMatchExplainedNone, wholly from
// kMatchExplainedAll, and never less than it once was. Two cameras that
// differ give 0.7-0.99 from the first samples, twins 0.4 at most
// (docs/design.md); continuous, so that the two engines, whose R^2 differ a
// little, apply nearly the same.
constexpr double kMatchExplainedNone = 0.45;
constexpr double kMatchExplainedAll = 0.75;
// Rotation between the two sightings of a sample, in units of the narrowest
// kernel's sigma: the lead is turned to the trail's heading to first order;
// the second order, about (dtheta / sigma)^2 / 2 of F, reads as black level
// (F'' runs along F). At the time of flight's 0.25 a matched rig turning at
// 0.05 rad/s learned 3 DN; 0.05 leaves 1.3e-3 of F, and a rig that turns all
// the time still learns a little from it (docs/design.md); 0.03 and below
// left the S-turns of near clutter nothing to learn from.
constexpr double kMatchMaxRotationSigma = 0.05;
// cam1's vignetting against cam0's is radial: a2 (x^2 + y^2) across the
// pixels, not a2 x^2 across the columns. A column sum averages the rows'
// share of it with the scene's own vertical layout, so the rows' share is
// taken from the frame: each column is also summed with weight y^2 (y the
// row's centre in units of half the width), the rows in this many rings from
// the top and bottom edges in (the outer sixth, the next sixth, the middle
// third), each weighed by its rows' mean y^2: the column sums' per-pixel work
// unchanged, a multiply per ring and column, not per pixel.
constexpr int kMatchRadialRings = 3;
// beta's unit (DN): the three columns of the Jacobian then have like sizes.
constexpr double kMatchOffsetUnitDn = 64.0;
// Parameters beyond these are not taken (a scene that fooled the samples):
// |a1|, |a2| and |beta| in DN.
constexpr double kMatchMaxShape = 0.5;
constexpr double kMatchMaxOffsetDn = 40.0;

}  // namespace lumavel::params
