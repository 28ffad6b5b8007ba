// Misalignment self-calibration: the yaw between the two cameras, measured
// from a recording without knowing it beforehand.
//
// In a translation, cam0 at some time stands where cam1 stood h earlier;
// there the two images differ only by a rotation: the misalignment plus the
// heading change (gyro). Frames rarely fall exactly there (at 3.5 m/s and
// 60 Hz a frame is 5.8 cm for an 8 cm baseline), and how far off they fall
// is unknown without the speed. So for every frame of cam1 the best lag and
// its neighbours are registered with cam0 in 12 tapered windows across the
// view: each window's shift is the misalignment plus a translation term that
// varies across the view (with depth, and as cos^2 of the angle on a plane).
// Regressing the shifts on that term's shape (averaged over neighbouring
// frames) and taking the intercept extrapolates to zero translation: one
// sample per frame. The median of the samples is the estimate; the spread of
// medians over blocks of 20 frames, with a resolution floor of 1/6 of a
// working column in quadrature, gives its uncertainty.
//
// A gyro that does not match the images (its sign flipped, a scale off)
// leaves part of each heading change in the samples, which then follow the
// gyro's turn: where the turns differ over the pass (straight, then turning)
// the slope of the samples against them, over blocks of 20 frames, beyond
// 0.5 at 5 sigma is refused, naming imu0/data.csv (a pass that turns alike
// throughout cannot tell such a gyro from a misalignment).
//
// Limits: on a single plane the translation term varies by only ~10 % across
// a 50 deg view, so the extrapolation amplifies registration noise ~10x; a
// gyro offset b adds b * (lag time) (see docs/results.md for figures).
#pragma once
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "lumavel/host/cli_fwd.hpp"
#include "lumavel/host/recording.hpp"

namespace lumavel::host {

struct CalibrationOptions {
  int width = 160;           // working columns (finer columns: finer shifts)
  double max_shift_deg = 6;  // search range of the rotation
  int max_lag = 60;          // frames
  double min_correlation = 0.95;
  // Called now and then with the stage ("reading frames", "registering"),
  // the work done and the total; optional.
  std::function<void(const char* stage, size_t done, size_t total)> progress;
};

struct Calibration {
  double misalignment = 0;   // rad, yaw from cam0 to cam1
  double uncertainty = 0;    // rad, 1 sigma: the spread over blocks of frames and the resolution floor
  size_t samples = 0;        // registered frame pairs used
  size_t candidates = 0;     // frames tried
  size_t same_image = 0;     // frames skipped: both cameras delivered the same image (no stereo difference)
  int width = 0, height = 0;  // working size the frames were registered at
};

// Throws RecordingError for a bad recording, std::runtime_error when no
// frame pair registers (no motion, no texture).
Calibration calibrate_misalignment(const Recording& rec, const CalibrationOptions& opt = {});

// Adds `lumavel-sim calibrate REC ...`.
void add_calibrate_command(cli::Tool& tool);

}  // namespace lumavel::host
