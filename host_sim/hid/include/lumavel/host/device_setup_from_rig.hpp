// The whole device configuration (DeviceConfig + lens tables) for the rig
// that made a recording: what `lumavel-sim calibrate REC --write FILE` sends
// to a board through `lumavel-read config set --file FILE`. Separate library
// (lumavel_device_setup: recordings and the reference engine, Eigen) so that
// lumavel-read, which only needs the text form, does not depend on them.
#pragma once
#include "lumavel/host/config_text.hpp"
#include "lumavel/host/rig.hpp"
#include "lumavel/host/settings.hpp"

namespace lumavel::host {

// From estimator settings in physical units. The device's model puts cam0's
// axis at exactly +-pi/2 (looking left/right) and cam1's at cam0's plus the
// misalignment; a yaw common to both cameras changes nothing in the kernel
// tables, so the settings' axes are rotated to that model (lens edges with
// them). Throws std::invalid_argument naming the field that the HID
// configuration cannot carry or that is out of its range.
DeviceSetup device_setup_from_settings(const EstimatorSettings& s);

// derive_settings(rec, size), with the misalignment replaced by
// `misalignment_rad` when it is finite (e.g. from calibrate_misalignment).
DeviceSetup device_setup_from_recording(const Recording& rec, WorkingSize size, double misalignment_rad);

}  // namespace lumavel::host
