// A camera frame stamped far closer to its predecessor than the recording's
// frame period (1 us after it, in both cameras' tables) is a timing glitch (a
// driver's clock read twice, a frame delivered twice with a new stamp), not a
// frame: the estimator took its interval as real, flagged it SATURATED then
// FRAME_GAP, and the two frames after it came out ~12 % off with no flag.
// Below kFrameGlitchPeriods of the median frame period such a pair is
// skipped, so the estimator sees a plain dropped frame (FRAME_GAP), counted
// and said once.
#pragma once
#include <string>
#include <vector>

#include "lumavel/host/recording.hpp"

namespace lumavel::host {

constexpr double kFrameGlitchPeriods = 0.5;

struct FrameGlitches {
  int count = 0;
  long first_line = 0;        // of the first one in cam0/data.csv
  uint64_t first_t_ns = 0;
  double first_interval_s = 0;
};

// Removes from `frames` each pair closer than kFrameGlitchPeriods x period_s
// to the last one kept; `lines[k]` is frames[k]'s line in the cam0 table.
FrameGlitches skip_frame_glitches(std::vector<FramePairEntry>& frames, const std::vector<long>& lines,
                                  double period_s);

// "1 frame pair skipped as a timing glitch (at CAM_CSV:12, t = ... ns, 1e-06 s
// after the previous frame: below half the median frame period 0.0166667 s)".
std::string format_frame_glitches(const FrameGlitches& g, const std::string& cam_csv, double period_s);

}  // namespace lumavel::host
