// Misalignment self-calibration: the yaw between the two cameras, measured
// from a recording without knowing it beforehand.
//
// In a translation, cam0 at frame j stands where cam1 stood at frame i
// (j - i frames later, h further on). There the two images differ only by a
// rotation: the misalignment plus the heading change between i and j (gyro).
// For every frame i the lag j and the angular shift that best register the
// column profiles (normalised cross-correlation, sub-column peak) give one
// sample of the misalignment; the median of all samples is the estimate and
// the scaled median absolute deviation over sqrt(n) its uncertainty.
#pragma once
#include <string>
#include <vector>

#include "lumavel/host/recording.hpp"

namespace lumavel::host {

struct CalibrationOptions {
  int width = 160;           // working columns (finer columns: finer shifts)
  double max_shift_deg = 6;  // search range of the rotation
  int max_lag = 60;          // frames
  double min_correlation = 0.95;
};

struct Calibration {
  double misalignment = 0;   // rad, yaw from cam0 to cam1
  double uncertainty = 0;    // rad, 1 sigma of the median
  size_t samples = 0;        // registered frame pairs used
  size_t candidates = 0;     // frames tried
};

// Throws RecordingError for a bad recording, std::runtime_error when no
// frame pair registers (no motion, no texture).
Calibration calibrate_misalignment(const Recording& rec, const CalibrationOptions& opt = {});

// `lumavel-sim calibrate REC ...`; argv[0] is "calibrate".
int calibrate_main(int argc, char** argv);

}  // namespace lumavel::host
