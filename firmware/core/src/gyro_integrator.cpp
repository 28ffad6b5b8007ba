#include "lumavel/core/gyro_integrator.hpp"

#include "lumavel/core/estimator_params.hpp"

namespace lumavel {
namespace {

// Longest interval integrated in one piece (params::kGyroMaxStep), in ns:
// also keeps |rate sum| * dt (|sum| <= 2^32) inside uint64.
constexpr uint64_t kMaxStepNs = static_cast<uint64_t>(fx::q_of(params::kGyroMaxStep * 1e9, 0));
static_assert(kMaxStepNs <= UINT64_MAX >> 32, "|rate sum| * dt must stay inside uint64");

// A rate sum (two Q7.24 rates, |sum| <= 2^32) times dt nanoseconds, over 2,
// is an angle in Q32 rad: sum * dt * 2^8 / 2e9 = sum * dt / kDivisor.
constexpr uint64_t kDivisor = 7812500;

// |sum| * dt (< 2^32 * 4e9 < 2^64) and its sign.
uint64_t magnitude(int64_t rate_sum, uint64_t dt_ns, bool* negative) {
  if (dt_ns > kMaxStepNs) dt_ns = kMaxStepNs;
  *negative = rate_sum < 0;
  return static_cast<uint64_t>(rate_sum < 0 ? -rate_sum : rate_sum) * dt_ns;
}

// The trapezoid of two rates whose sum is given (no halving of the sum
// first: the truncating (r0 + r1) / 2 lost half an LSB of rate on every odd
// sum, 1.3e-3 rad a day with the rate to one side), rounded half away from zero.
int64_t angle_of_sum(int64_t rate_sum, uint64_t dt_ns) {
  bool neg = false;
  const uint64_t m = magnitude(rate_sum, dt_ns, &neg);
  const auto a = static_cast<int64_t>(fx::udiv_trunc(m + kDivisor / 2, kDivisor));
  return neg ? -a : a;
}

}  // namespace

void GyroIntegrator::reset() { *this = GyroIntegrator{}; }

void GyroIntegrator::push(uint64_t t_ns, RateQ24 rate) {
  if (count_ == 0) {
    t_[1] = t_ns;
    r_[1] = rate;
    angle_[1] = 0;
    sum_ = 0;
    sum_rem_ = 0;
    t_first_ = t_ns;
    count_ = 1;
    return;
  }
  if (t_ns <= t_[1]) return;  // out of order: ignore (the host refuses such input)
  const uint64_t dt = t_ns - t_[1];
  if (dt > max_spacing_) max_spacing_ = dt;
  t_[0] = t_[1];
  r_[0] = r_[1];
  angle_[0] = angle_[1];
  t_[1] = t_ns;
  r_[1] = rate;
  // Trapezoid between the two samples, added exactly (quotient and
  // remainder): no rounding accumulates however long the stream runs.
  bool neg = false;
  const uint64_t m = magnitude(int64_t{r_[0]} + r_[1], dt, &neg);
  uint64_t rem = 0;
  const auto q = static_cast<int64_t>(fx::udiv_trunc(m, kDivisor, &rem));
  const auto r = static_cast<int64_t>(rem);
  sum_ += neg ? -q : q;
  sum_rem_ += neg ? -r : r;
  if (sum_rem_ < 0) {
    sum_rem_ += static_cast<int64_t>(kDivisor);
    --sum_;
  } else if (sum_rem_ >= static_cast<int64_t>(kDivisor)) {
    sum_rem_ -= static_cast<int64_t>(kDivisor);
    ++sum_;
  }
  angle_[1] = sum_ + (2 * sum_rem_ >= static_cast<int64_t>(kDivisor) ? 1 : 0);  // rounded once
  ++count_;
  if (fx::rate_at_rail(r_[0]) || fx::rate_at_rail(r_[1])) {
    railed_ = true;
    railed_end_ = t_ns;
  }
}

bool GyroIntegrator::saturated_since(uint64_t from_ns) const {
  if (count_ == 0) return false;
  return fx::rate_at_rail(r_[1]) || (railed_ && railed_end_ > from_ns);
}

int64_t GyroIntegrator::angle_at(uint64_t t_ns) const { return fx::shr_round(angle_q32(t_ns), 4); }

int64_t GyroIntegrator::angle_q32(uint64_t t_ns) const {
  if (count_ == 0) return 0;
  if (t_ns >= t_[1]) return angle_[1] + angle_of_sum(2 * int64_t{r_[1]}, t_ns - t_[1]);
  if (count_ < 2 || t_ns <= t_[0]) {
    // Before the window: hold the oldest rate backwards.
    const uint64_t ref = count_ < 2 ? t_[1] : t_[0];
    const int64_t a = count_ < 2 ? angle_[1] : angle_[0];
    const RateQ24 r = count_ < 2 ? r_[1] : r_[0];
    return a - angle_of_sum(2 * int64_t{r}, ref - t_ns);
  }
  // Inside [t0, t1]: exact integral of the linear rate from t0 to t.
  const uint64_t span = t_[1] - t_[0];
  const uint64_t dt = t_ns - t_[0];
  // Rate at t by linear interpolation, position in Q16 (|dr| < 2^32).
  const int64_t frac_q16 = fx::div_q(static_cast<int64_t>(dt), static_cast<int64_t>(span), 16);
  const int64_t rate_t = r_[0] + fx::shr_round((int64_t{r_[1]} - r_[0]) * frac_q16, 16);
  return angle_[0] + angle_of_sum(r_[0] + rate_t, dt);
}

bool GyroIntegrator::covers(uint64_t from_ns, uint64_t to_ns, uint64_t gap_ns) const {
  if (count_ == 0) return false;
  if (from_ns > to_ns) {
    const uint64_t t = from_ns;
    from_ns = to_ns;
    to_ns = t;
  }
  if (t_first_ > from_ns + gap_ns) return false;  // the stream starts inside the interval
  if (to_ns > t_[1] + gap_ns) return false;       // held at the last rate beyond the stream
  const uint64_t oldest = count_ < 2 ? t_[1] : t_[0];
  if (to_ns + gap_ns < oldest) return false;      // held backwards before the window
  const bool hole = count_ >= 2 && t_[1] - t_[0] > gap_ns;
  return !(hole && t_[0] < to_ns && t_[1] > from_ns);
}

uint64_t GyroIntegrator::take_max_spacing() {
  const uint64_t m = max_spacing_;
  max_spacing_ = 0;
  return m;
}

}  // namespace lumavel
