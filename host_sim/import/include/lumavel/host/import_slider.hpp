// `lumavel-sim import-slider DATA_DIR OUT_REC [--baseline H]`: turns a
// single-camera slider recording (Event-Camera Dataset layout, e.g.
// slider_depth) into a two-camera recording in the project's EuRoC layout,
// cam1 synthesised by time shift (time_shift_pairing.hpp), gyro zero.
#pragma once
#include <cstddef>
#include <string>

#include "lumavel/host/cli_fwd.hpp"

namespace lumavel::host {

// Default baseline: above the frame spacing (~1.2 cm at the slider's
// ~0.3 m/s and ~38 ms frame period) so that the blend's error is a fraction
// of h, yet short, because on slider_depth V comes out biased low roughly in
// proportion to h beyond ~2 cm (measured sweep: docs/real-recording.md).
constexpr double kDefaultSliderBaseline = 0.02;

struct ImportSliderOptions {
  double baseline = kDefaultSliderBaseline;  // m, cam1 ahead of cam0
  double imu_rate_hz = 100;
  bool force = false;  // replace an existing OUT/mav0 (else it is refused)
};

struct ImportSliderSummary {
  size_t frames_in = 0;         // frames of the dataset
  size_t pairs = 0;             // frame pairs written
  size_t imu_samples = 0;
  size_t groundtruth_samples = 0;
  double max_blend_gap_m = 0;   // largest spacing of two blended frames
};

// Throws RecordingError (bad input, named file and line) or std::runtime_error.
ImportSliderSummary import_slider(const std::string& data_dir, const std::string& out_rec,
                                  const ImportSliderOptions& options = {});

// Adds `lumavel-sim import-slider` (exit status 0 done, 1 failure, 2 usage).
void add_import_slider_command(cli::Tool& tool);
// The command alone; argv[0] is "import-slider".
int import_slider_main(int argc, char** argv);

}  // namespace lumavel::host
