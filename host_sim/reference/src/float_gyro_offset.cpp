// Twin of firmware/core/src/gyro_offset.cpp.
#include "lumavel/host/float_gyro_offset.hpp"

#include <cmath>

#include "lumavel/core/estimator_params.hpp"

namespace lumavel::host {
namespace {
// A still period this long renews the reference, in integer ns as the core.
constexpr uint64_t kRenewNs = static_cast<uint64_t>(fx::q_of(params::kGyroOffsetRenewal * 1e9, 0));
}  // namespace

void FloatGyroOffset::anchor(const FloatStillnessInput& in) {
  ref_ = *in.cur;
  t_ref_ = in.t_ns;
  angle_ref_ = in.angle_raw;
  have_ref_ = true;
  still_ = false;
}

void FloatGyroOffset::update(const FloatStillnessInput& in) {
  if (!in.textured) {
    drop_reference();
    return;
  }
  if (!have_ref_ || in.t_ns <= t_ref_) {
    anchor(in);
    return;
  }
  // Displacement since the reference, read as a translation: h dM.S / S.S.
  const FloatStereoMeasurement& m = *in.cur;
  const double den = m.diff.squaredNorm();
  if (den <= 0) {
    have_ref_ = false;
    return;
  }
  const double d = in.baseline * (m.mid - ref_.mid).dot(m.diff) / den;
  if (std::fabs(d) > in.still_distance) {
    anchor(in);  // moved: a new candidate period starts here
    return;
  }
  // Each camera's own change, read as a turn and scaled as above (the core's comment).
  for (int i = 0; i < 2; ++i) {
    const double rr = m.r[i].norm();
    if (rr <= 0) continue;
    if (std::fabs(in.baseline * (m.f[i] - ref_.f[i]).dot(m.r[i]) / (rr * std::sqrt(den))) > params::kStillCameraFactor * in.still_distance) {
      anchor(in);
      return;
    }
  }
  const uint64_t span_ns = in.t_ns - t_ref_;  // compared in integer ns, as the core
  still_ = span_ns >= in.still_min_ns;
  if (still_) {
    // Mean rate since the reference; renewed as the core: not still again until still_min has passed.
    offset_ = (in.angle_raw - angle_ref_) / (static_cast<double>(span_ns) * 1e-9);
    if (span_ns > kRenewNs) anchor(in);
  }
}

}  // namespace lumavel::host
