#include "lumavel/host/render/sensor_synthesis.hpp"

#include <cmath>
#include <sstream>

#include "lumavel/host/render/random.hpp"
#include "lumavel/host/render/stereo_rig.hpp"

namespace lumavel::host::render {

void body_rates(const BodyState& b, double w[3]) {
  // Level (no vibration): the yaw rate alone, bit for bit as before tilts existed.
  if (b.pitch == 0.0 && b.roll == 0.0 && b.pitch_rate == 0.0 && b.roll_rate == 0.0) {
    w[0] = w[1] = 0;
    w[2] = b.yaw_rate;
    return;
  }
  // ZYX Euler rates (heading, pitch, roll) -> body-frame angular rate of
  // R = yaw(heading) Ry(pitch) Rx(roll).
  const double sp = std::sin(b.pitch), cp = std::cos(b.pitch), sr = std::sin(b.roll), cr = std::cos(b.roll);
  w[0] = b.roll_rate - sp * b.yaw_rate;
  w[1] = cr * b.pitch_rate + sr * cp * b.yaw_rate;
  w[2] = -sr * b.pitch_rate + cr * cp * b.yaw_rate;
}

void specific_force(const BodyState& b, double f[3]) {
  // In the level (yawed) frame: tangential, centripetal (towards the turn),
  // and gravity's reaction plus the heave acceleration on z. The lever arm of
  // the tilting is nil: the IMU sits at the body origin.
  f[0] = b.accel;
  f[1] = b.speed * b.yaw_rate;
  f[2] = b.az == 0.0 ? kGravity : kGravity + b.az;
  if (b.pitch == 0.0 && b.roll == 0.0) return;
  // Into the tilted body frame.
  const Eigen::Vector3d fb = body_tilt(b).transpose() * Eigen::Vector3d(f[0], f[1], f[2]);
  for (int k = 0; k < 3; ++k) f[k] = fb[k];
}

std::vector<ImuSample> synthesize_imu(const Scenario& s, const Trajectory& traj) {
  const ImuSpec& m = s.imu;
  const int64_t period = static_cast<int64_t>(std::llround(1e9 / m.rate_hz));
  const int64_t first = static_cast<int64_t>(std::llround(m.offset_s * 1e9));
  const double gyro_sigma = m.gyro_noise_density * std::sqrt(m.rate_hz);
  const double accel_sigma = m.accel_noise_density * std::sqrt(m.rate_hz);
  Rng gyro_rng(stream_seed(s.seed, 2));
  Rng accel_rng(stream_seed(s.seed, 4));
  std::vector<ImuSample> out;
  for (int64_t k = 0;; ++k) {
    const int64_t rel = first + k * period;
    const double t = static_cast<double>(rel) * 1e-9;
    if (t > s.duration_s) break;
    if (s.start_ns + rel < 0) continue;
    const BodyState b = traj.at(t);
    ImuSample x;
    x.t_ns = static_cast<uint64_t>(s.start_ns + rel);
    double w[3];
    body_rates(b, w);
    // The x and y rates are added only when the body tilts, so that a level
    // body's noise-only samples keep their bits (0 + noise is the noise, but
    // -0 would not survive it).
    const bool tilted = w[0] != 0.0 || w[1] != 0.0;
    x.w[0] = gyro_sigma > 0 ? gyro_sigma * gyro_rng.gaussian() : 0.0;
    x.w[1] = gyro_sigma > 0 ? gyro_sigma * gyro_rng.gaussian() : 0.0;
    if (tilted) {
      x.w[0] += w[0];
      x.w[1] += w[1];
    }
    x.w[2] = w[2] + m.gyro_bias_z + (gyro_sigma > 0 ? gyro_sigma * gyro_rng.gaussian() : 0.0);
    specific_force(b, x.a);
    if (accel_sigma > 0)
      for (double& a : x.a) a += accel_sigma * accel_rng.gaussian();
    out.push_back(x);
  }
  return out;
}

GroundTruthSample groundtruth_at(const Scenario& s, const BodyState& b, uint64_t t_ns) {
  GroundTruthSample g;
  g.t_ns = t_ns;
  g.p[0] = b.x;
  g.p[1] = b.y;
  g.p[2] = b.z;
  if (b.pitch == 0.0 && b.roll == 0.0) {
    g.q[0] = std::cos(0.5 * b.heading);
    g.q[1] = 0;
    g.q[2] = 0;
    g.q[3] = std::sin(0.5 * b.heading);
  } else {
    // The rotation of body_attitude as the product of its three turns' quaternions
    // (w's sign continuing the level one's, which a matrix's conversion would not keep).
    const Eigen::Quaterniond q = Eigen::Quaterniond(Eigen::AngleAxisd(b.heading, Eigen::Vector3d::UnitZ())) *
                                 Eigen::Quaterniond(Eigen::AngleAxisd(b.pitch, Eigen::Vector3d::UnitY())) *
                                 Eigen::Quaterniond(Eigen::AngleAxisd(b.roll, Eigen::Vector3d::UnitX()));
    g.q[0] = q.w();
    g.q[1] = q.x();
    g.q[2] = q.y();
    g.q[3] = q.z();
  }
  // The path's velocity plus the heave's: the body origin's, in the world.
  g.v[0] = b.speed * std::cos(b.heading);
  g.v[1] = b.speed * std::sin(b.heading);
  g.v[2] = b.vz;
  g.bw[2] = s.imu.gyro_bias_z;
  return g;
}

std::vector<GroundTruthSample> synthesize_groundtruth(const Scenario& s, const Trajectory& traj) {
  const int64_t period = static_cast<int64_t>(std::llround(1e9 / s.groundtruth_rate_hz));
  std::vector<GroundTruthSample> out;
  for (int64_t rel = 0; static_cast<double>(rel) * 1e-9 <= s.duration_s + 1e-12; rel += period)
    out.push_back(groundtruth_at(s, traj.at(static_cast<double>(rel) * 1e-9),
                                 static_cast<uint64_t>(s.start_ns + rel)));
  return out;
}

std::vector<bool> dropped_frames(const Scenario& s, int n_frames) {
  std::vector<bool> drop(static_cast<size_t>(n_frames), false);
  for (int i : s.dropped_frames)
    if (i >= 0 && i < n_frames) drop[static_cast<size_t>(i)] = true;
  if (s.drop_rate > 0) {
    Rng rng(stream_seed(s.seed, 3));
    for (int i = 0; i < n_frames; ++i)
      if (rng.uniform() < s.drop_rate) drop[static_cast<size_t>(i)] = true;
  }
  return drop;
}

CameraSensor camera_sensor(const Scenario& s, const StereoRig& rig, int cam) {
  const Pinhole& p = rig.pinhole();
  CameraSensor c;
  c.rate_hz = s.camera.rate_hz;
  c.width = p.width;
  c.height = p.height;
  c.fu = p.fu;
  c.fv = p.fv;
  c.cu = p.cu;
  c.cv = p.cv;
  c.distortion.assign(p.lens.k.begin(), p.lens.k.end());
  const RigidPose& T = rig.T_BS(cam);
  for (int r = 0; r < 3; ++r) {
    for (int k = 0; k < 3; ++k) c.T_BS[static_cast<size_t>(4 * r + k)] = T.R(r, k);
    c.T_BS[static_cast<size_t>(4 * r + 3)] = T.t[r];
  }
  c.T_BS[12] = c.T_BS[13] = c.T_BS[14] = 0;
  c.T_BS[15] = 1;
  c.exposure_s = s.camera.exposure_frames / s.camera.rate_hz;
  c.comment = "lumavel-sim render: " + s.file + " cam" + std::to_string(cam);
  // The renderer's truth, for a person reading the file; no tool uses it.
  const PhotometricSpec& ph = s.camera.photometric[static_cast<size_t>(cam)];
  if (!ph.ideal()) {
    std::ostringstream os;
    os << "; photometric" << (s.camera.photometric_preset.empty() ? "" : " (" + s.camera.photometric_preset + ")")
       << ": gain " << ph.gain << ", black level " << ph.black_level << ", vignetting [" << ph.vignetting[0]
       << ", " << ph.vignetting[1] << "], prnu " << ph.prnu << ", dsnu " << ph.dsnu << ", column "
       << ph.column_gain << " / " << ph.column_offset << ", gamma " << ph.gamma << ", auto-exposure "
       << ph.auto_exposure.sigma;
    c.comment += os.str();
  }
  return c;
}

ImuSensor imu_sensor(const Scenario& s) {
  ImuSensor m;
  m.rate_hz = s.imu.rate_hz;
  m.gyroscope_noise_density = s.imu.gyro_noise_density;
  m.gyroscope_random_walk = s.imu.gyro_random_walk;
  m.comment = "lumavel-sim render: " + s.file + " (gyro bias z " + std::to_string(s.imu.gyro_bias_z) +
              " rad/s)";
  return m;
}

}  // namespace lumavel::host::render
