// Integrates the yaw rate over time (trapezoid between samples) and answers
// the heading at any time inside or just past the sample stream.
#pragma once
#include <cstdint>

#include "lumavel/core/fixed.hpp"

namespace lumavel {

class GyroIntegrator {
 public:
  void reset();
  void push(uint64_t t_ns, RateQ24 rate);
  // Integrated angle at t (unwrapped, Q28 in int64): interpolated between the
  // last two samples, held at the last rate beyond the last one.
  int64_t angle_at(uint64_t t_ns) const;
  bool has_samples() const { return count_ > 0; }
  // Longest spacing between samples seen since the last call (ns).
  uint64_t take_max_spacing();

 private:
  int64_t angle_q32(uint64_t t_ns) const;

  uint64_t t_[2]{};
  RateQ24 r_[2]{};
  int64_t angle_[2]{};  // integrated angle at t_[i], Q32 (16x finer than the result:
                        // 1000 rounded steps a second stay below 1e-8 rad)
  uint32_t count_ = 0;
  uint64_t max_spacing_ = 0;
};

}  // namespace lumavel
