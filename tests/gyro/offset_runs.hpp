// The gyro-offset scenario rendered small (with its zero-rate offset and,
// from the same seed, without it), then estimated with and without offset
// learning, with the figures the test checks: the learned offset, and the
// mean V error at standstill and while cruising after it.
#pragma once
#include <string>
#include <vector>

#include "lumavel/host/engine.hpp"
#include "lumavel/host/render/scenario.hpp"
#include "lumavel/host/run_metrics.hpp"

namespace lumavel::host::gyro_test {

struct Rendered {
  std::string with_offset, without_offset;  // recording folders
  render::Scenario scenario;                // as rendered (overrides applied, offset on)
  // Timeline read from the scenario: the first segment is the standstill,
  // the second the acceleration; cruising starts at the end of the second.
  double still_end_s = 0, cruise_start_s = 0;
};
// Renders `scenario_file` at width x height for duration_s into two folders
// under `dir`. Throws when the scenario does not start with a standstill
// followed by one more segment, or has no gyro offset.
Rendered render_both(const std::string& scenario_file, int width, int height, double duration_s,
                     const std::string& dir);

struct OffsetRun {
  std::vector<TrackPoint> track;
  RunMetrics metrics;
  double offset = 0;          // learned offset at the end of the run, rad/s
  double still_s = 0;         // time flagged still (kStatusStill)
  double last_still_t = -1;   // scenario time of the last still frame, s (-1: none)
  double mean_err_still = 0;  // mean V error in [1 s, still end): learned by then, m/s
  double mean_err_cruise = 0; // mean V error from cruise start to the end, m/s
};
OffsetRun run_offset(const std::string& rec_dir, const Rendered& r, EngineKind engine, bool learning,
                     int work_width, int work_height);

// One line of figures for the test log.
std::string describe(const OffsetRun& run);

}  // namespace lumavel::host::gyro_test
