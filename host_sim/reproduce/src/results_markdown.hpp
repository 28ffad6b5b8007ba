// Results of the studies and their Markdown page (docs/results.md).
#pragma once
#include <string>
#include <vector>

#include "lumavel/host/engine.hpp"
#include "lumavel/host/recording.hpp"
#include "lumavel/host/run_metrics.hpp"
#include "sections.hpp"
#include "studies.hpp"

namespace lumavel::host::reproduce {

// What the status flags say about a run.
struct FlagBehaviour {
  int low_texture = 0, no_light = 0, frame_gaps = 0, restarts = 0, frames = 0;
  double longest_hold_s = 0;    // longest stretch of held V (low texture or no light)
  double drift_in_hold = 0;     // max |V - V at the start of the stretch| inside it, m/s
  double recovery_s = -1;       // from the end of that stretch to |err| < 5 % of |V| (-1: never)
};
FlagBehaviour flag_behaviour(const std::vector<TrackPoint>& track);

// Mean signed error after `settle_s` relative to the mean |V| there, percent.
double bias_percent(const std::vector<TrackPoint>& track, double settle_s = 1.0);
// RMS error after `settle_s`, m/s.
double rms_after(const std::vector<TrackPoint>& track, double settle_s = 1.0);

struct CaseResult {
  Case c;
  WorkSize work{0, 0};
  EngineKind engine = EngineKind::kFixed;
  RunMetrics metrics;
  FlagBehaviour behaviour;
  GapReport gaps;
  double run_s = 0;
  double step_us = 0;       // engine compute time per frame (push_gyro + step), microseconds
  double bias_percent = 0;  // mean signed error after 1 s over mean |V| after 1 s
  double rms_after = 0;     // RMS error after 1 s, m/s
  std::string plot;  // relative to the results page, fixed engine only
  double gyro_offset = 0;         // learned zero-rate offset at the end of the run, rad/s
  std::vector<TrackPoint> track;  // the estimates, for studies with their own figures
  WorkSize rendered{0, 0};        // the recording's resolution, as rendered
  double rendered_s = 0;          // and its length, s
};

struct StudyResult {
  Study study;
  std::vector<CaseResult> cases;
};

// The lens study's table (study_lens.cpp): per scene and working size, the
// undistorted, corrected, column-table and ignored runs side by side; adds
// issue 11's targets.
std::string lens_table(const StudyResult& sr, std::vector<SectionTarget>& targets);

// The gyro offset study's table (study_gyro_offset.cpp); adds its targets.
std::string gyro_offset_table(const StudyResult& sr, std::vector<SectionTarget>& targets);

// How the page was made, for its header.
struct PageInfo {
  bool quick = false;
  std::string only;           // --only TEXT ("" for all studies)
  double seconds = 0;         // the whole run
  double render_seconds = 0;  // of which rendering
  int renders_reused = 0;     // renders from an earlier run, their time not counted
  std::string machine;        // what it ran on (machine_description)
};

// `sections` (sections.hpp) follow the studies; their targets join the table.
std::string results_markdown(const std::vector<StudyResult>& results, const std::vector<Section>& sections,
                             const PageInfo& info);

}  // namespace lumavel::host::reproduce
