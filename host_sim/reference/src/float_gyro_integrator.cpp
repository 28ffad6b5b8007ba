// Twin of firmware/core/src/gyro_integrator.cpp.
#include "lumavel/host/float_gyro_integrator.hpp"

#include <algorithm>
#include <cmath>

#include "lumavel/core/estimator_params.hpp"
#include "lumavel/host/settings.hpp"

namespace lumavel::host {

void FloatGyroIntegrator::push(uint64_t t_ns, double rate) {
  const RateQ24 q = to_fixed_rate(rate);  // throws if not finite
  const bool rail = fx::rate_at_rail(q);
  if (rail) rate = std::ldexp(static_cast<double>(q), -fx::kRateFrac);
  if (count_ == 0) {
    t_[1] = t_ns;
    r_[1] = rate;
    at_rail_[1] = rail;
    angle_[1] = 0;
    t_first_ = t_ns;
    count_ = 1;
    return;
  }
  if (t_ns <= t_[1]) return;
  const double dt = static_cast<double>(t_ns - t_[1]) * 1e-9;
  max_spacing_ = std::max(max_spacing_, t_ns - t_[1]);
  t_[0] = t_[1];
  r_[0] = r_[1];
  angle_[0] = angle_[1];
  at_rail_[0] = at_rail_[1];
  t_[1] = t_ns;
  r_[1] = rate;
  at_rail_[1] = rail;
  angle_[1] = angle_[0] + (r_[0] + r_[1]) / 2 * std::min(dt, params::kGyroMaxStep);  // one piece at most, as the core
  if (at_rail_[0] || at_rail_[1]) {
    railed_ = true;
    railed_end_ = t_ns;
  }
  ++count_;
}

double FloatGyroIntegrator::angle_at(uint64_t t) const {
  if (count_ == 0) return 0;
  auto secs = [](uint64_t a, uint64_t b) { return (static_cast<double>(a) - static_cast<double>(b)) * 1e-9; };
  constexpr double kMax = params::kGyroMaxStep;  // held rates extrapolate this far at most
  if (t >= t_[1]) return angle_[1] + r_[1] * std::min(secs(t, t_[1]), kMax);
  if (count_ < 2) return angle_[1] - r_[1] * std::min(secs(t_[1], t), kMax);
  if (t <= t_[0]) return angle_[0] - r_[0] * std::min(secs(t_[0], t), kMax);
  const double span = secs(t_[1], t_[0]), dt = secs(t, t_[0]);
  const double rate_t = r_[0] + (r_[1] - r_[0]) * dt / span;
  return angle_[0] + (r_[0] + rate_t) / 2 * dt;
}

uint64_t FloatGyroIntegrator::take_max_spacing() {
  const uint64_t m = max_spacing_;
  max_spacing_ = 0;
  return m;
}

bool FloatGyroIntegrator::covers(uint64_t from, uint64_t to, uint64_t gap) const {
  if (count_ == 0) return false;
  if (from > to) std::swap(from, to);
  if (t_first_ > from + gap || to > t_[1] + gap) return false;
  const uint64_t oldest = count_ < 2 ? t_[1] : t_[0];
  if (to + gap < oldest) return false;
  const bool hole = count_ >= 2 && t_[1] - t_[0] > gap;
  return !(hole && t_[0] < to && t_[1] > from);
}

bool FloatGyroIntegrator::saturated_since(uint64_t from) const {
  return count_ > 0 && (at_rail_[1] || (railed_ && railed_end_ > from));
}

}  // namespace lumavel::host
