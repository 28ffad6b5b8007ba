#include "lumavel/core/gyro_offset.hpp"

#include "lumavel/core/estimator_params.hpp"
#include "lumavel/core/imath.hpp"

namespace lumavel {
namespace {
// A still period this long renews the reference (params::kGyroOffsetRenewal), ns.
constexpr uint64_t kRenewNs = static_cast<uint64_t>(fx::q_of(params::kGyroOffsetRenewal * 1e9, 0));
// Each camera's bound in still distances, Q4.
constexpr int64_t kStillCameraFactorQ4 = fx::q_of(params::kStillCameraFactor, 4);
}  // namespace

void GyroOffset::anchor(const StillnessInput& in) {
  ref_ = *in.cur;
  t_ref_ = in.t_ns;
  angle_ref_ = in.angle_raw;
  have_ref_ = true;
  still_ = false;
}

// Each camera's own change since the reference, read as a turn and scaled
// as the stereo reading in update(), h dF_i.R_i / (|R_i| |S|), and held to
// kStillCameraFactor of its bound. Where the texture repeats every 2h along
// the path, the two cameras see inverted profiles and M stands still while
// the rig moves (stripes of 16 cm at h = 8 cm: STILL at 1 m/s, the turn
// learned as offset). den: |S|^2 as in update(), Q52.
// (dF in Q24 and R in Q16: products below 2^53, kMaxKernels of them below 2^56.)
bool GyroOffset::camera_moved(const StillnessInput& in, int64_t den) const {
  const int64_t s_norm = fx::isqrt64(static_cast<uint64_t>(den));  // Q26
  for (int i = 0; i < 2; ++i) {
    int64_t num = 0, rr = 0;
    for (uint8_t k = 0; k < in.cur->count; ++k) {
      const int64_t r = fx::shr_round(in.cur->r[i][k], 4);  // Q16
      num += fx::shr_round(int64_t{in.cur->f[i][k]} - ref_.f[i][k], 4) * r;  // Q40
      rr += r * r;                                                            // Q32
    }
    const int64_t norms = s_norm * fx::isqrt64(static_cast<uint64_t>(rr));  // Q42, < 2^60
    if (norms == 0) continue;
    bool sat = false;
    const int64_t d = fx::shr_round(int64_t{fx::div_q(num, norms, fx::kValueFrac + 2, &sat)} * in.baseline, fx::kValueFrac);
    const int64_t bound = (kStillCameraFactorQ4 * in.still_distance) >> 4;
    if (sat || d > bound || d < -bound) return true;
  }
  return false;
}

void GyroOffset::update(const StillnessInput& in) {
  if (!in.textured) {
    have_ref_ = false;
    still_ = false;
    return;
  }
  if (!have_ref_ || in.t_ns <= t_ref_) {
    anchor(in);
    return;
  }
  // Displacement since the reference, read as a translation: h * dM.S / S.S.
  int64_t num = 0, den = 0;
  for (uint8_t k = 0; k < in.cur->count; ++k) {
    const int64_t s = in.cur->diff[k] / 4;  // Q26: four kernels' products stay in int64
    num += (int64_t{in.cur->mid[k]} - ref_.mid[k]) / 4 * s;
    den += s * s;
  }
  if (den == 0) {
    have_ref_ = false;
    return;
  }
  bool sat = false;
  const int64_t d = fx::shr_round(int64_t{fx::div_q(num, den, fx::kValueFrac, &sat)} * in.baseline, fx::kValueFrac);
  if (sat || d > in.still_distance || d < -int64_t{in.still_distance} || camera_moved(in, den)) {
    anchor(in);  // moved: a new candidate period starts here
    return;
  }
  const uint64_t span = in.t_ns - t_ref_;
  still_ = span >= uint64_t{in.still_min_us} * 1000;
  if (still_) {
    // Mean rate since the reference: Q28 rad over ns -> Q24 rad/s (* 1e9 / 16).
    offset_ = fx::div_q((in.angle_raw - angle_ref_) * 62500000, static_cast<int64_t>(span), 0);
    if (span > kRenewNs) {
      const RateQ24 keep = offset_;
      anchor(in);
      offset_ = keep;
    }
  }
}

int64_t GyroOffset::take_angle_over(int64_t dt_ns) {
  // Q24 rad/s * ns -> Q28 rad: * 16 / 1e9. Whole seconds apart, so that no
  // gap overflows; the remainder of the rest carried (floor division).
  constexpr int64_t kNsPerS = 1000000000, kDiv = 62500000;
  int64_t ns = 0, r = 0;
  const int64_t secs = fx::div_trunc(dt_ns, kNsPerS, &ns);
  const int64_t x = int64_t{offset_} * ns + angle_rem_;  // |.| < 2^31 * 1e9 + kDiv < 2^61
  int64_t q = fx::div_trunc(x, kDiv, &r);
  if (r < 0) {
    r += kDiv;
    --q;
  }
  angle_rem_ = r;
  return int64_t{offset_} * 16 * secs + q;
}

}  // namespace lumavel
