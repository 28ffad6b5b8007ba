// Accuracy of an estimate track against ground truth, as the paper reports it
// (Zarrouati et al. 2012, eq. 22) plus the usual extras. Shared by `run` and
// `reproduce`.
#pragma once
#include "lumavel/core/status.hpp"
#include <cstdint>
#include <string>
#include <vector>

namespace lumavel::host {

struct TrackPoint {
  uint64_t t_ns = 0;
  double v_est = 0;   // m/s
  double v_true = 0;  // m/s; NaN where there is no ground truth
  uint16_t status = 0;  // lumavel::StatusFlag bits of the estimate
};

// E weighs each frame by the time since the previous frame, at most this
// many median frame intervals: a pause of the recording (an hour between two
// frames) does not weigh as its length (it made E one frame's error).
constexpr double kMaxWeightIntervals = 10;

struct MetricOptions {
  double min_speed = 0.05;  // |V| below this is left out of E (relative error blows up)
  double settle_s = 1.0;    // "after the first second": convergence excluded
};

struct RunMetrics {
  size_t samples = 0;            // all points
  size_t with_truth = 0;         // points with ground truth
  size_t excluded_slow = 0;      // left out of E: |V| < min_speed
  double e_percent = 0;          // eq. 22: time average of |V_est - V| / |V|, percent
  double l1_percent = 0;         // sum |err| / sum |V|, percent
  double rms = 0;                // m/s, all points with truth
  double worst_after = 0;        // max |err| after settle_s, m/s
  double worst_after_t = 0;      // its time since the first point, s
  double mean_abs_after = 0;     // mean |err| after settle_s, m/s
  double mean_after = 0;         // mean signed err (bias) after settle_s, m/s
  size_t after_count = 0;        // points after settle_s with truth
  size_t not_finite = 0;         // estimates that are NaN or infinite: left out of every figure
  double span_s = 0;             // from the first point to the last, s
  MetricOptions options;
};

// Each point weighs the time since the previous one (the first: the median
// interval), so E is a time average even across frame gaps.
RunMetrics compute_metrics(const std::vector<TrackPoint>& track, const MetricOptions& options = {});

// Multi-line human summary (no trailing newline). A figure that cannot be
// computed is replaced by why (no ground truth, too slow, too short), never
// printed as nan or inf.
std::string format_metrics(const RunMetrics& m);

// A fault: a flag saying the estimate is held, degraded or missing. CONVERGING,
// STILL and NO_TOF tell how the estimate is made, not that it is wrong.
bool is_fault(StatusFlag flag);

// How many points carry each status flag (lumavel::kStatusFlags order).
struct FlagCounts {
  size_t frames = 0;
  size_t flagged = 0;   // points with a fault flag (is_fault)
  size_t count[sizeof(kStatusFlags) / sizeof(kStatusFlags[0])] = {};
};
FlagCounts count_flags(const std::vector<TrackPoint>& track);

// "flags, frames of 600: SATURATED 600 (saturated pixels or arithmetic), ..."
// or "flags, frames of 600: none raised" (no trailing newline).
std::string format_flag_counts(const FlagCounts& c);

}  // namespace lumavel::host
