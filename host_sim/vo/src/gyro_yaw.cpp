#include "lumavel/host/vo/gyro_yaw.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace lumavel::host::vo {
namespace {

double seconds(uint64_t later, uint64_t earlier) {
  return (static_cast<double>(later) - static_cast<double>(earlier)) * 1e-9;
}

}  // namespace

void GyroYaw::push(uint64_t t_ns, double rate_z) {
  if (!std::isfinite(rate_z)) throw std::invalid_argument("gyro rate is not a finite number");
  if (!samples_.empty() && t_ns <= samples_.back().t) return;
  samples_.push_back({t_ns, rate_z});
}

double GyroYaw::rate_at(uint64_t t) const {
  if (t <= samples_.front().t) return samples_.front().rate;
  if (t >= samples_.back().t) return samples_.back().rate;
  const auto hi = std::lower_bound(samples_.begin(), samples_.end(), t,
                                   [](const Sample& s, uint64_t x) { return s.t < x; });
  const auto lo = hi - 1;
  const double w = seconds(t, lo->t) / seconds(hi->t, lo->t);
  return lo->rate + w * (hi->rate - lo->rate);
}

GyroYaw::Interval GyroYaw::between(uint64_t t0, uint64_t t1) {
  Interval out;
  if (samples_.empty() || t1 <= t0) {
    out.max_spacing = seconds(t1, t0);
    return out;
  }
  // Knots: t0, every sample strictly inside, t1.
  uint64_t prev_t = t0;
  double prev_rate = rate_at(t0);
  out.max_spacing = std::max(seconds(samples_.front().t, t0), seconds(t1, samples_.back().t));
  for (size_t i = 0; i < samples_.size(); ++i) {
    const Sample& s = samples_[i];
    if (i > 0 && s.t > t0 && samples_[i - 1].t < t1) out.max_spacing = std::max(out.max_spacing, seconds(s.t, samples_[i - 1].t));
    if (s.t <= t0 || s.t >= t1) continue;
    out.yaw += 0.5 * (prev_rate + s.rate) * seconds(s.t, prev_t);
    prev_t = s.t;
    prev_rate = s.rate;
  }
  out.yaw += 0.5 * (prev_rate + rate_at(t1)) * seconds(t1, prev_t);
  // Keep the last sample at or before t1: the next interval starts there.
  while (samples_.size() > 1 && samples_[1].t <= t1) samples_.pop_front();
  return out;
}

}  // namespace lumavel::host::vo
