// True forward velocity V_xb from EuRoC ground truth: the x component of
// q_RS^-1 * v_RS_R, linearly interpolated at the requested timestamps.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "lumavel/host/recording.hpp"

namespace lumavel::host {

// The plausibility rules of ground truth (the bounds of recording_layout.hpp),
// shared by the recording reader and import-slider: "" when the value is
// within its bound, else the reason, e.g. "1e+06 m/s is beyond +-1000 m/s
// (...)". Callers name the file, line and column before it.
std::string why_implausible_position(double p_m);
std::string why_implausible_speed(double v_mps);
std::string why_not_unit_quaternion(double norm);

// "" when the velocities follow the positions (layout::kGroundTruthRate*),
// or the positions are one point throughout (not given: a file may fill the
// velocity alone, all V is compared with); otherwise the reason, naming the
// stretch furthest apart by its lines (`line[i]` is sample i's line of the
// file) and saying what the velocity must be. Callers name the file and
// `at_line`, set to the stretch's first line.
std::string why_velocity_is_not_the_positions_rate(const std::vector<GroundTruthSample>& gt,
                                                   const std::vector<long>& line, long& at_line);

// V_xb at one ground-truth sample (q need not be normalised; it is).
double body_forward_velocity(const GroundTruthSample& g);

// V_xb at each of `t_ns` (sorted); NaN outside the ground truth's time span
// and inside its holes (layout::kGroundTruthMaxHoleIntervals).
std::vector<double> true_forward_velocity(const std::vector<GroundTruthSample>& gt,
                                          const std::vector<uint64_t>& t_ns);

}  // namespace lumavel::host
