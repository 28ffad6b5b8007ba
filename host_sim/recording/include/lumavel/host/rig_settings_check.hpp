// One rule for every command that reads a rig (run, calibrate, reproduce):
// the settings derived from a recording must be ones the firmware core takes,
// and a refusal names the file (and key) the offending value came from.
#pragma once
#include <string>

#include "lumavel/host/recording.hpp"
#include "lumavel/host/settings.hpp"

namespace lumavel::host {

// The file (and key) an EstimatorSettings member ("cam[1].fu", "baseline",
// "frame_period", ...) is derived from, for messages.
std::string setting_source(const Recording& rec, const std::string& setting);

// Quantises `s` as the core takes it (to_fixed_config); throws RecordingError
// "FILE: key: value: rule" for the first setting it cannot take.
void check_rig_settings(const Recording& rec, const EstimatorSettings& s);

// For the commands that write a recording (render, import-slider): a valid
// input can still give a recording that `run` refuses (no baseline, a focal
// length beyond the core's range at its working size, every frame dropped):
// throws "OUT/mav0 was written, but lumavel-sim run refuses it: " + run's
// reason, when `run` at its default working size would.
void check_runnable(const std::string& out);

// The same rules before anything is written, on the recording about to be
// written (render, import-slider): `rec` holds its cameras, frame and gyro
// times and periods, at least one frame, and rec.root the mav0 folder it
// will be written to (for the messages), and its gyro and ground-truth
// samples. Checks the intrinsics, that there are gyro samples, that each
// gyro and ground-truth value is one run reads (check_sample_values), that
// the gyro covers the frames, and the rig's settings;
// throws RecordingError "FILE: rule" as run would on reading it.
void check_runnable_unwritten(Recording& rec);

}  // namespace lumavel::host
