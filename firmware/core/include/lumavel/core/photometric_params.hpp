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

}  // namespace lumavel::params
