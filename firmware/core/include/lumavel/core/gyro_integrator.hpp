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
  // Longest spacing between samples seen since the last call (ns).
  uint64_t take_max_spacing();
  // Whether the samples cover the interval [from, to] to within `gap_ns`:
  // there are samples, the stream started no later than from + gap, the
  // angle at `to` is not extrapolated more than gap past the newest sample
  // (or before the older one of the window), and the window's two samples
  // are not a hole (spaced more than gap) overlapping the interval. Holes
  // among samples pushed since the last frame are take_max_spacing()'s.
  bool covers(uint64_t from_ns, uint64_t to_ns, uint64_t gap_ns) const;
  // Whether the angle since `from` rests on a sample at the RateQ24 rail
  // (fx::rate_at_rail): a trapezoid with a railed end after `from`, or the
  // hold beyond a railed newest sample.
  bool saturated_since(uint64_t from_ns) const;

 private:
  int64_t angle_q32(uint64_t t_ns) const;

  uint64_t t_[2]{};
  RateQ24 r_[2]{};
  int64_t angle_[2]{};  // integrated angle at t_[i], Q32 (16x finer than the result), rounded
  // The exact integral at t_[1]: sum_ + sum_rem_ / 7812500 in Q32 (sum_rem_
  // in [0, 7812500)), so that no rounding adds up over a day of samples.
  int64_t sum_ = 0;
  int64_t sum_rem_ = 0;
  uint32_t count_ = 0;
  uint64_t t_first_ = 0;  // time of the first sample since reset
  bool railed_ = false;   // a trapezoid has had a railed end
  uint64_t railed_end_ = 0;  // end of the latest such trapezoid
  uint64_t max_spacing_ = 0;
};

}  // namespace lumavel
