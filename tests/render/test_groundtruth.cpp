// Ground truth consistency: velocity is the derivative of position, heading
// rate the yaw rate, V_xb = x of q^-1 v is the signed speed, and segments
// join continuously.
#include <CppUTest/TestHarness.h>

#include <cmath>

#include "lumavel/host/groundtruth.hpp"
#include "lumavel/host/render/sensor_synthesis.hpp"
#include "lumavel/host/render/trajectory.hpp"
#include "render_test_support.hpp"

using namespace lumavel::host;
using namespace lumavel::host::render;

namespace {

TrajectorySpec mixed_trajectory() {
  TrajectorySpec t;
  t.x0 = 1;
  t.y0 = -2;
  t.heading0_deg = 30;
  auto seg = [&](SegmentKind k, double T, double v0, double v1, SpeedProfile p, double curv) {
    SegmentSpec g;
    g.kind = k;
    g.duration_s = T;
    g.v0 = v0;
    g.v1 = v1;
    g.profile = p;
    g.curvature = curv;
    t.segments.push_back(g);
  };
  seg(SegmentKind::Straight, 2, 0.5, 0.55, SpeedProfile::Linear, 0);
  seg(SegmentKind::Arc, 3, 0.55, 0.6, SpeedProfile::Linear, 1.0 / 15);
  seg(SegmentKind::Straight, 2, 0.6, -0.4, SpeedProfile::Smooth, 0);  // reversal
  seg(SegmentKind::Arc, 2, -0.4, -0.4, SpeedProfile::Linear, -1.0 / 3);
  return t;
}

}  // namespace

TEST_GROUP(GroundTruth){};

TEST(GroundTruth, VelocityIsTheDerivativeOfPosition) {
  const Trajectory traj(mixed_trajectory());
  const double dt = 1e-5;
  for (double t = 0.013; t < 9.5; t += 0.0971) {
    const BodyState a = traj.at(t - dt), b = traj.at(t + dt), m = traj.at(t);
    DOUBLES_EQUAL(m.speed * std::cos(m.heading), (b.x - a.x) / (2 * dt), 1e-6);
    DOUBLES_EQUAL(m.speed * std::sin(m.heading), (b.y - a.y) / (2 * dt), 1e-6);
    DOUBLES_EQUAL(m.yaw_rate, (b.heading - a.heading) / (2 * dt), 1e-6);
    DOUBLES_EQUAL(m.accel, (b.speed - a.speed) / (2 * dt), 1e-5);
  }
}

TEST(GroundTruth, SegmentsJoinContinuously) {
  const Trajectory traj(mixed_trajectory());
  for (double tb : {2.0, 5.0, 7.0}) {
    const BodyState a = traj.at(tb - 1e-9), b = traj.at(tb + 1e-9);
    DOUBLES_EQUAL(a.x, b.x, 1e-8);
    DOUBLES_EQUAL(a.y, b.y, 1e-8);
    DOUBLES_EQUAL(a.heading, b.heading, 1e-8);
    DOUBLES_EQUAL(a.speed, b.speed, 1e-7);
  }
}

TEST(GroundTruth, ArcKeepsItsRadius) {
  const Trajectory traj(mixed_trajectory());
  const BodyState s = traj.at(2.0);
  // Left turn: centre 15 m to the left of the heading.
  const double cx = s.x - 15 * std::sin(s.heading), cy = s.y + 15 * std::cos(s.heading);
  for (double t = 2.0; t <= 5.0; t += 0.25) {
    const BodyState b = traj.at(t);
    DOUBLES_EQUAL(15.0, std::hypot(b.x - cx, b.y - cy), 1e-9);
  }
  DOUBLES_EQUAL(0.575 * 3 / 15, traj.at(5.0).heading - s.heading, 1e-12);  // mean speed * T / R
}

TEST(GroundTruth, RowsGiveTheSignedForwardVelocity) {
  render::Scenario s = test::empty_scenario(40, 30);
  s.trajectory = mixed_trajectory();
  s.duration_s = 9;
  s.imu.gyro_bias_z = 0.01;
  const Trajectory traj(s.trajectory);
  const auto gt = synthesize_groundtruth(s, traj);
  CHECK_EQUAL(static_cast<size_t>(9 * 200 + 1), gt.size());
  bool saw_negative = false;
  for (size_t k = 0; k < gt.size(); ++k) {
    const double t = static_cast<double>(gt[k].t_ns - static_cast<uint64_t>(s.start_ns)) * 1e-9;
    const BodyState b = traj.at(t);
    // The recording library's reading of the row: x of q^-1 v.
    DOUBLES_EQUAL(b.speed, body_forward_velocity(gt[k]), 1e-12);
    saw_negative = saw_negative || b.speed < -0.1;
    DOUBLES_EQUAL(0.01, gt[k].bw[2], 0);
    if (k > 0) {
      // Position differences match the mean velocity over the step.
      const double dt = 0.005;
      DOUBLES_EQUAL(0.5 * (gt[k].v[0] + gt[k - 1].v[0]) * dt, gt[k].p[0] - gt[k - 1].p[0], 1e-6);
      DOUBLES_EQUAL(0.5 * (gt[k].v[1] + gt[k - 1].v[1]) * dt, gt[k].p[1] - gt[k - 1].p[1], 1e-6);
    }
  }
  CHECK(saw_negative);
}
