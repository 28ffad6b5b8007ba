// Renders a whole scenario into a recording folder (EuRoC layout) with a
// pool of worker threads; images are written by the workers, the csv files
// in timestamp order afterwards.
#pragma once
#include <string>

#include "lumavel/host/render/scenario.hpp"

namespace lumavel::host::render {

struct RenderOptions {
  int threads = 2;
  bool progress = true;  // progress on stderr (cli::Progress: a bar on a terminal, else a line every few seconds)
};

struct RenderSummary {
  int frames = 0;           // frame pairs in the scenario
  int dropped = 0;          // pairs not written
  int max_subframes = 0;
  double max_background = 0;  // largest fraction of an image showing background
  int max_background_frame = -1;
  size_t imu_samples = 0, groundtruth_samples = 0;
  double seconds = 0;       // wall-clock render time
};

// `out_dir` is REC: writes REC/mav0/... Throws on any error (message names
// the file).
RenderSummary render_recording(const Scenario& s, const std::string& out_dir,
                               const RenderOptions& opt = {});

}  // namespace lumavel::host::render
