// Rig vibration: the gyro measures the body-frame rate of the rendered
// attitude, the accelerometer its specific force, the ground truth carries
// the full attitude and the heave velocity, the cameras tilt with the body,
// and a scenario without vibration is the level one, bit for bit.
#include <CppUTest/TestHarness.h>

#include <cmath>
#include <cstring>

#include "lumavel/host/groundtruth.hpp"
#include "lumavel/host/render/sensor_synthesis.hpp"
#include "lumavel/host/render/stereo_rig.hpp"
#include "lumavel/host/render/trajectory.hpp"
#include "lumavel/host/render/vibration.hpp"
#include "render_test_support.hpp"

using namespace lumavel::host;
using namespace lumavel::host::render;

namespace {
constexpr double kPi = 3.14159265358979323846;

// A turning pass (arc left, then right) with a trolley's shake.
render::Scenario shaking(double pitch_deg, double roll_deg, double heave_m) {
  render::Scenario s = test::turning_pass(40, 30, 20);
  s.trajectory.heading0_deg = 200;  // past pi: the level quaternion's signs as before
  s.vibration.pitch_rms_deg = pitch_deg;
  s.vibration.roll_rms_deg = roll_deg;
  s.vibration.heave_rms_m = heave_m;
  s.vibration.freq_lo_hz = 2;
  s.vibration.freq_hi_hz = 15;
  return s;
}

double seconds(const render::Scenario& s, uint64_t t_ns) {
  return static_cast<double>(t_ns - static_cast<uint64_t>(s.start_ns)) * 1e-9;
}

Eigen::Matrix3d from_quaternion(const double q[4]) {
  return Eigen::Quaterniond(q[0], q[1], q[2], q[3]).toRotationMatrix();
}

double pitch_of(const Eigen::Matrix3d& R) { return std::asin(-R(2, 0)); }
double roll_of(const Eigen::Matrix3d& R) { return std::atan2(R(2, 1), R(2, 2)); }
}  // namespace

TEST_GROUP(Vibration){};

// The sign conventions checked against the attitude itself, not the formula:
// w = vee(R^T dR/dt) by central differences of body_attitude.
TEST(Vibration, GyroIsTheBodyRateOfTheRenderedAttitude) {
  const render::Scenario s = shaking(3, 2, 0.005);
  const Trajectory traj(s);
  const auto imu = synthesize_imu(s, traj);
  CHECK(imu.size() > 3000);
  double largest_xy = 0;
  for (const auto& m : imu) {
    const double t = seconds(s, m.t_ns), dt = 1e-6;
    const Eigen::Matrix3d R = body_attitude(traj.at(t));
    const Eigen::Matrix3d W =
        R.transpose() * (body_attitude(traj.at(t + dt)) - body_attitude(traj.at(t - dt))) / (2 * dt);
    DOUBLES_EQUAL(W(2, 1), m.w[0], 1e-6);
    DOUBLES_EQUAL(W(0, 2), m.w[1], 1e-6);
    DOUBLES_EQUAL(W(1, 0), m.w[2], 1e-6);
    largest_xy = std::max(largest_xy, std::max(std::fabs(m.w[0]), std::fabs(m.w[1])));
  }
  CHECK(largest_xy > 0.1);  // the shake is there to be measured
}

// f = R^T (d2p/dt2 + g z): second differences of the rendered position.
TEST(Vibration, AccelerometerIsTheTiltedSpecificForce) {
  const render::Scenario s = shaking(3, 2, 0.005);
  const Trajectory traj(s);
  const auto imu = synthesize_imu(s, traj);
  for (size_t k = 0; k < imu.size(); k += 7) {
    const double t = seconds(s, imu[k].t_ns), dt = 1e-4;
    const BodyState a = traj.at(t - dt), b = traj.at(t), c = traj.at(t + dt);
    const Eigen::Vector3d acc((a.x - 2 * b.x + c.x) / (dt * dt), (a.y - 2 * b.y + c.y) / (dt * dt),
                              (a.z - 2 * b.z + c.z) / (dt * dt));
    const Eigen::Vector3d f = body_attitude(b).transpose() * (acc + Eigen::Vector3d(0, 0, kGravity));
    for (int i = 0; i < 3; ++i) DOUBLES_EQUAL(f[i], imu[k].a[i], 2e-3);
  }
}

// The quaternion is body_attitude's; its pitch and roll have the rms asked
// for; v is the derivative of p, heave included; V_xb reads along tilted x.
TEST(Vibration, GroundTruthCarriesTheFullAttitudeAndHeave) {
  const render::Scenario s = shaking(1.0, 0.5, 0.003);
  const Trajectory traj(s);
  const auto gt = synthesize_groundtruth(s, traj);
  double p2 = 0, r2 = 0, h2 = 0;
  for (size_t k = 0; k < gt.size(); ++k) {
    const BodyState b = traj.at(seconds(s, gt[k].t_ns));
    const Eigen::Matrix3d R = from_quaternion(gt[k].q);
    CHECK((R - body_attitude(b)).cwiseAbs().maxCoeff() < 1e-12);
    p2 += pitch_of(R) * pitch_of(R);
    r2 += roll_of(R) * roll_of(R);
    h2 += (gt[k].p[2] - s.trajectory.z) * (gt[k].p[2] - s.trajectory.z);
    const Eigen::Vector3d v(gt[k].v[0], gt[k].v[1], gt[k].v[2]);
    DOUBLES_EQUAL((R.transpose() * v)[0], body_forward_velocity(gt[k]), 1e-12);
    // x of Ry(pitch)^T (speed, 0, vz): the tilted axis sees the path's speed and the heave.
    DOUBLES_EQUAL(b.speed * std::cos(b.pitch) - std::sin(b.pitch) * b.vz, body_forward_velocity(gt[k]), 1e-12);
    if (k > 0) {
      const double dt = 0.005;
      DOUBLES_EQUAL(0.5 * (gt[k].v[2] + gt[k - 1].v[2]) * dt, gt[k].p[2] - gt[k - 1].p[2], 2e-5);
    }
  }
  const double n = static_cast<double>(gt.size());
  DOUBLES_EQUAL(1.0, std::sqrt(p2 / n) * 180 / kPi, 0.15);
  DOUBLES_EQUAL(0.5, std::sqrt(r2 / n) * 180 / kPi, 0.075);
  DOUBLES_EQUAL(0.003, std::sqrt(h2 / n), 0.00045);
}

// Each camera is posed by the tilted body: camera_in_world = body_in_world * T_BS.
TEST(Vibration, CamerasTiltWithTheBody) {
  render::Scenario s = shaking(2, 1, 0.01);
  const Trajectory traj(s);
  const StereoRig rig(s.camera);
  double largest = 0;
  for (double t = 0; t < 2; t += 0.013) {
    const BodyState b = traj.at(t);
    const RigidPose c = rig.camera_in_world(0, b);
    const Eigen::Matrix3d R = body_attitude(b);
    CHECK((c.R - R * rig.T_BS(0).R).cwiseAbs().maxCoeff() < 1e-15);
    CHECK((c.t - (R * rig.T_BS(0).t + Eigen::Vector3d(b.x, b.y, b.z))).cwiseAbs().maxCoeff() < 1e-15);
    // The optical axis (body y, looking left) leaves the horizontal by the roll.
    DOUBLES_EQUAL(std::sin(b.roll) * std::cos(b.pitch), (c.R * Eigen::Vector3d::UnitZ())[2], 1e-12);
    largest = std::max(largest, std::fabs(b.roll));
  }
  CHECK(largest > 0.5 * kPi / 180);
  // and the image moves: frame 0 is not the level one's
  s.trajectory.heading0_deg = 0;  // looking left at the wall
  render::Scenario level = s;
  level.vibration = VibrationSpec{};
  s.planes.push_back(test::wall_at(2, -10, 10, -1, 1, test::checker(0.2, 0, 255)));
  level.planes = s.planes;
  CHECK(test::radiance(s) != test::radiance(level));
}

// The phases come from the seed: the same seed the same motion, another seed
// another; the axes differ from each other.
TEST(Vibration, SeededAndDifferentPerAxis) {
  VibrationSpec v;
  v.pitch_rms_deg = v.roll_rms_deg = 1;
  v.freq_lo_hz = 3;
  v.freq_hi_hz = 11;
  const Vibration a(v, 7), b(v, 7), c(v, 8);
  double same = 0, other = 0, axes = 0;
  for (double t = 0; t < 3; t += 0.01) {
    same = std::max(same, std::fabs(a.at(t).pitch - b.at(t).pitch));
    other = std::max(other, std::fabs(a.at(t).pitch - c.at(t).pitch));
    axes = std::max(axes, std::fabs(a.at(t).pitch - a.at(t).roll));
  }
  DOUBLES_EQUAL(0, same, 0);
  CHECK(other > 0.005);
  CHECK(axes > 0.005);
  // A band of one frequency is one tone of the rms asked for.
  v.freq_lo_hz = v.freq_hi_hz = 5;
  const Vibration one(v, 7);
  double m2 = 0;
  int n = 0;
  for (double t = 0; t < 10; t += 0.001, ++n) m2 += one.at(t).pitch * one.at(t).pitch;
  DOUBLES_EQUAL(1.0, std::sqrt(m2 / n) * 180 / kPi, 0.01);
}

// No vibration (no block, or one of zero amplitudes): the level body's gyro,
// accelerometer, ground truth and images, bit for bit.
TEST(Vibration, NoneLeavesEverythingLevel) {
  render::Scenario s = shaking(0, 0, 0);
  s.imu.gyro_noise_density = 0.001;
  s.imu.accel_noise_density = 0.01;
  s.imu.gyro_bias_z = -0.02;
  const Trajectory with(s), without(s.trajectory);
  const auto ia = synthesize_imu(s, with), ib = synthesize_imu(s, without);
  CHECK_EQUAL(ia.size(), ib.size());
  for (size_t k = 0; k < ia.size(); ++k) {
    CHECK(std::memcmp(ia[k].w, ib[k].w, sizeof ia[k].w) == 0);
    CHECK(std::memcmp(ia[k].a, ib[k].a, sizeof ia[k].a) == 0);
  }
  const auto ga = synthesize_groundtruth(s, with);
  for (const auto& g : ga) {
    const BodyState b = without.at(seconds(s, g.t_ns));
    CHECK(g.q[1] == 0.0 && g.q[2] == 0.0 && !std::signbit(g.q[1]) && !std::signbit(g.q[2]));
    DOUBLES_EQUAL(std::cos(0.5 * b.heading), g.q[0], 0);
    DOUBLES_EQUAL(std::sin(0.5 * b.heading), g.q[3], 0);
    CHECK(g.v[2] == 0.0 && !std::signbit(g.v[2]));
    DOUBLES_EQUAL(b.z, g.p[2], 0);
  }
  s.trajectory.heading0_deg = 0;  // looking left at the wall
  s.planes.push_back(test::wall_at(2, -10, 10, -1, 1, test::checker(0.2, 0, 255)));
  render::Scenario none = s;
  none.vibration = VibrationSpec{};
  CHECK(test::radiance(s) == test::radiance(none));
}
