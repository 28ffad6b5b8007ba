// Body yaw from the gyro between two frame times: the trapezoid rule over
// the samples, linearly interpolated at the frame times (the runner pushes
// every sample up to the first one at or after each frame).
#pragma once
#include <cstdint>
#include <deque>

namespace lumavel::host::vo {

class GyroYaw {
 public:
  // Samples in time order; older or repeated timestamps are ignored. Throws
  // std::invalid_argument for a rate that is not a finite number.
  void push(uint64_t t_ns, double rate_z);

  struct Interval {
    double yaw = 0;          // rad, integral of the rate over [t0, t1]
    double max_spacing = 0;  // s, largest sample spacing covering the interval (or its extrapolated ends)
  };
  // Integral over [t0, t1] (t0 < t1); extrapolates the nearest rate beyond
  // the samples. Forgets samples that no later interval needs.
  Interval between(uint64_t t0_ns, uint64_t t1_ns);

 private:
  struct Sample {
    uint64_t t;
    double rate;
  };
  double rate_at(uint64_t t) const;
  std::deque<Sample> samples_;
};

}  // namespace lumavel::host::vo
