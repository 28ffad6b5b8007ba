// Planar body trajectory made of straight and arc segments with a linear or
// smooth (raised-cosine) speed profile per segment, evaluated analytically so
// ground truth, gyro and camera poses agree exactly. Before the first and
// after the last segment the motion continues at the end speed/curvature.
// A scenario's vibration (vibration.hpp) tilts and heaves the body about
// that path.
#pragma once
#include <vector>

#include "lumavel/host/render/scenario.hpp"
#include "lumavel/host/render/vibration.hpp"

namespace lumavel::host::render {

struct BodyState {
  double x = 0, y = 0, z = 0;   // body origin in the world, m
  double heading = 0;           // yaw of body x from world x, rad (CCW)
  double speed = 0;             // V_xb, m/s (signed)
  double yaw_rate = 0;          // rad/s
  double accel = 0;             // d(speed)/dt, m/s^2
  double curvature = 0;         // 1/m
  // Vibration (all 0 without): attitude R = yaw(heading) Ry(pitch) Rx(roll);
  // z above includes the heave.
  double pitch = 0, roll = 0;            // rad
  double pitch_rate = 0, roll_rate = 0;  // rad/s
  double vz = 0, az = 0;                 // heave velocity m/s, acceleration m/s^2
};

class Trajectory {
 public:
  explicit Trajectory(const TrajectorySpec& spec, Vibration vibration = {});
  // The scenario's path with its vibration (phases from its seed).
  explicit Trajectory(const Scenario& s);
  BodyState at(double t) const;
  double end_time() const { return starts_.empty() ? 0 : starts_.back().t + segs_.back().duration_s; }

 private:
  struct Start {
    double t, x, y, heading;
  };
  // State `dt` into segment `g` that began at `s`; dt may exceed the segment.
  static BodyState advance(const SegmentSpec& g, const Start& s, double dt, double z);
  std::vector<SegmentSpec> segs_;
  std::vector<Start> starts_;
  double z_ = 0;
  Vibration vib_;
};

}  // namespace lumavel::host::render
