// The two cameras are not photometric twins: gain, black level, vignetting
// and fixed pattern differ by several percent between two cheap sensors, and
// any difference that a common gain (cancelled by the division by N) does
// not explain reads as S = h dF/dx, i.e. as velocity.
//
// For twins, over a travel L long against h, S_k = F_k(x + h) - F_k(x) has
// zero mean whatever the scene and its depth (its integral telescopes to
// h (F(end) - F(start)) / L). What cam1 adds to it on average, per kernel,
// is learned as that mean over travel (a standstill teaches nothing). The end
// term is removed sample by sample with the stereo prediction
// h (dM - dtheta Rbar) / d of the frame's displacement d, whose sum
// telescopes the same way: what is left is cam1's offset b_k. d / h is the
// interval's own least squares on S as corrected. Not the fused V: an error
// of V leaves that error times S in every sample, and the twin, whose V
// differs within its allowance, learned another b_k (the day soak split the
// time of flight on 4x more frames). The weights and the lead keep 1e-5 of
// themselves for the same reason. b_k is subtracted from cam1's F_k before
// S, M and the phases are formed (measurement.hpp) once kBalanceReadyLength
// of travel has been averaged, so that d / h sees the offset removed early.
// What it does not learn: a difference that follows the scene (a contrast
// or a vignetting shape that differs), clipping in one camera only.
//
// Formats: b_k in Q28 (ValueQ28); travel in Q24 m; the travel weight alpha
// in Q30; the lead h / d in Q20, |.| <= 2 kBalanceMaxLeadSteps; the least
// squares' sums in Q56 (S and dM held within +-2).
#pragma once
#include <cstdint>

#include "lumavel/core/fixed.hpp"
#include "lumavel/core/limits.hpp"
#include "lumavel/core/photometric_params.hpp"

namespace lumavel {

struct StereoMeasurement;

struct BalanceInput {
  const StereoMeasurement* prev;
  const StereoMeasurement* cur;
  AngleQ28 dtheta;         // integrated gyro over the interval
  LengthQ24 baseline;      // h (signed: x of cam1 minus x of cam0)
};

class PhotometricBalance {
 public:
  void reset();
  // Learns from one interval (measurements as corrected: their `balance`
  // gives back the raw values).
  void learn(const BalanceInput& in);
  // cam1's offset b_k; 0 until ready().
  ValueQ28 offset(uint8_t k) const { return ready() ? mean_s_[k] : 0; }
  bool ready() const { return learned_q24_ >= kReadyQ24; }

 private:
  static constexpr int64_t kLengthQ24 = fx::q_of(params::kBalanceLength, 24);
  static constexpr int64_t kReadyQ24 = fx::q_of(params::kBalanceReadyLength, 24);

  int64_t learned_q24_ = 0;  // travel averaged so far (Q24 m), held at kLengthQ24
  ValueQ28 mean_s_[kMaxKernels]{};  // b_k: the mean residual of S
};

}  // namespace lumavel
