// Parameters of the photometric balance (photometric_balance.hpp): one source
// for the firmware core (integer constants built from these at compile time)
// and the double-precision twin. None is tuned to one recording.
#pragma once

namespace lumavel::params {

// Travel over which the balance is averaged (m): a running mean until this
// much has been seen, an exponential average in travel after. The correction
// is applied from then on; before, the two cameras are taken as they are.
// (Measured on the photo wall, the street and near clutter: applied after
// 1 m, or with a slope on M_k as well, it hurt near clutter and reversals by
// up to 10 points; see docs/design.md.)
constexpr double kBalanceLength = 4.0;
// Frames whose displacement is below |h| / kBalanceMaxLeadSteps teach nothing
// (the stereo prediction h dM / d would amplify the noise of dM beyond this).
constexpr double kBalanceMaxLeadSteps = 64.0;
// Frames that turn more than this per metre teach nothing (rad/m): the
// rotation term of the stereo prediction is first order only, and its error
// (the field of view's, see velocity_observer.hpp) would read as cam1's offset.
constexpr double kBalanceMaxCurvature = 0.05;

}  // namespace lumavel::params
