// The stereo VO behind the host Engine interface, so that `lumavel-sim run
// --engine vo`, `reproduce` and the benchmarks drive it like lumavel's two
// engines, on the same binned frames. It is built from the recording
// (camera models, lenses, poses), not from EstimatorSettings.
#pragma once
#include <memory>

#include "lumavel/host/engine.hpp"
#include "lumavel/host/recording.hpp"

namespace lumavel::host {

// Throws RecordingError naming the sensor.yaml for a rig the VO cannot use
// (vo/stereo_rig.hpp). Estimates: gyro_offset is always 0 (the VO takes the
// gyro as it reads); texture is the number of tracks that agreed on the
// interval's motion (RANSAC inliers).
std::unique_ptr<Engine> make_vo_engine(const Recording& rec, int width, int height, bool ignore_distortion = false);

}  // namespace lumavel::host
