// True forward velocity V_xb from EuRoC ground truth: the x component of
// q_RS^-1 * v_RS_R, linearly interpolated at the requested timestamps.
#pragma once
#include <cstdint>
#include <vector>

#include "lumavel/host/recording.hpp"

namespace lumavel::host {

// V_xb at one ground-truth sample (q need not be normalised; it is).
double body_forward_velocity(const GroundTruthSample& g);

// V_xb at each of `t_ns` (sorted); NaN outside the ground truth's time span.
std::vector<double> true_forward_velocity(const std::vector<GroundTruthSample>& gt,
                                          const std::vector<uint64_t>& t_ns);

}  // namespace lumavel::host
