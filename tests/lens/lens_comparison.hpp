// One scenario rendered twice from the same seed (through its lens, and with
// the lens removed), then estimated four ways: undistorted, distorted with
// the correction (frames undistorted, the default), distorted with column
// tables only (--lens-columns), distorted read as pinhole (--ignore-distortion).
#pragma once
#include <string>
#include <vector>

#include "lumavel/host/engine.hpp"
#include "lumavel/host/render/scenario.hpp"
#include "lumavel/host/run_metrics.hpp"
#include "lumavel/host/run_recording.hpp"

namespace lumavel::host::lens_test {

struct Render {
  std::string scenario;  // path of the scenario YAML (it must have a lens)
  int width = 80, height = 60;
  double duration_s = 3;
};

// The two recordings (folders under `dir`) of a Render.
struct RenderedPair {
  std::string undistorted, distorted;
  render::Scenario scenario;  // as rendered through the lens (overrides applied)
};
RenderedPair render_pair(const Render& r, const std::string& dir);

struct Variant {
  std::vector<TrackPoint> track;
  RunMetrics metrics;
};

struct Comparison {
  Variant undistorted, corrected, columns, ignored;
  // Per-frame difference from the undistorted estimate after the first
  // second, fitted as slope * yaw rate: the spurious V a lens error leaves
  // in the rotation term (m/s per rad/s), and the rms of the difference.
  double corrected_slope = 0, columns_slope = 0, ignored_slope = 0;
  double corrected_rms = 0, columns_rms = 0, ignored_rms = 0;
};
// band: the elevation band as run would choose it (by the field of view), or forced.
Comparison compare(const RenderedPair& p, EngineKind engine, int work_width, int work_height,
                   RunOptions::Band band = RunOptions::Band::kByView);

// One line of figures for the test log.
std::string describe(const Comparison& c);

}  // namespace lumavel::host::lens_test
