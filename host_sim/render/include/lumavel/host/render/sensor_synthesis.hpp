// Everything of the recording besides the images, derived from the same
// analytic trajectory: gyro/accelerometer samples, ground truth, sensor.yaml
// contents and the list of dropped frames.
#pragma once
#include <vector>

#include "lumavel/host/recording.hpp"
#include "lumavel/host/render/scenario.hpp"
#include "lumavel/host/render/stereo_rig.hpp"
#include "lumavel/host/render/trajectory.hpp"

namespace lumavel::host::render {

constexpr double kGravity = 9.81;

// The body-frame angular rate of body_attitude(b) (level: 0, 0, yaw rate).
void body_rates(const BodyState& b, double w[3]);
// The body origin's specific force in the body frame: tangential,
// centripetal, +g and the heave acceleration on world z, rotated by the tilt.
void specific_force(const BodyState& b, double f[3]);

// imu0 at its own rate from `offset_s`: w = body_rates + (on z) bias + white
// noise (sigma = density * sqrt(rate)); accelerometer = specific_force + noise.
std::vector<ImuSample> synthesize_imu(const Scenario& s, const Trajectory& traj);

// EuRoC ground truth at groundtruth_rate_hz over [0, duration].
std::vector<GroundTruthSample> synthesize_groundtruth(const Scenario& s, const Trajectory& traj);
GroundTruthSample groundtruth_at(const Scenario& s, const BodyState& b, uint64_t t_ns);

// true for each frame index whose pair is lost (listed, or drawn at `drop_rate`).
std::vector<bool> dropped_frames(const Scenario& s, int n_frames);

CameraSensor camera_sensor(const Scenario& s, const StereoRig& rig, int cam);
ImuSensor imu_sensor(const Scenario& s);

}  // namespace lumavel::host::render
