// The double twin of firmware/core/gyro_integrator.hpp: the trapezoid
// between samples and the angle at any time inside or just past the stream,
// within the core's limits (its rate range, its longest piece).
#pragma once
#include <cstdint>

namespace lumavel::host {

class FloatGyroIntegrator {
 public:
  // rate in rad/s; what the fixed engine cannot represent is clipped to its
  // RateQ24 range, as there (throws if not finite).
  void push(uint64_t t_ns, double rate);
  // The rest as GyroIntegrator's (read its header), angles in rad.
  double angle_at(uint64_t t_ns) const;
  uint64_t take_max_spacing();
  bool covers(uint64_t from_ns, uint64_t to_ns, uint64_t gap_ns) const;
  bool saturated_since(uint64_t from_ns) const;

 private:
  // The last two samples ([1] the newer), with the core's member names.
  uint64_t t_[2]{};           // sample times, ns
  double r_[2]{};             // rates, rad/s
  double angle_[2]{};         // integrated angle at each sample, rad
  bool at_rail_[2]{};         // the sample was clipped to the range
  int count_ = 0;             // samples since the start
  uint64_t t_first_ = 0;      // first sample since the start
  bool railed_ = false;       // a trapezoid has had a clipped end ...
  uint64_t railed_end_ = 0;   // ... ending here
  uint64_t max_spacing_ = 0;  // longest sample spacing since the last take_max_spacing, ns
};

}  // namespace lumavel::host
