#include "lumavel/host/render/trajectory.hpp"

#include <cmath>

namespace lumavel::host::render {
namespace {
constexpr double kPi = 3.14159265358979323846;

// Distance, speed and acceleration `dt` into a segment. Outside [0, T] the
// speed is held at the nearest end value.
void profile(const SegmentSpec& g, double dt, double& dist, double& v, double& a) {
  const double T = g.duration_s;
  const double dv = g.v1 - g.v0;
  if (dt < 0) {
    v = g.v0;
    a = 0;
    dist = g.v0 * dt;
    return;
  }
  const double tc = dt < T ? dt : T;
  if (g.profile == SpeedProfile::Linear) {
    v = g.v0 + dv * tc / T;
    a = dt < T ? dv / T : 0;
    dist = g.v0 * tc + 0.5 * dv * tc * tc / T;
  } else {
    // v = v0 + dv (1 - cos(pi t / T)) / 2: zero acceleration at both ends.
    const double w = kPi / T;
    v = g.v0 + 0.5 * dv * (1 - std::cos(w * tc));
    a = dt < T ? 0.5 * dv * w * std::sin(w * tc) : 0;
    dist = g.v0 * tc + 0.5 * dv * (tc - std::sin(w * tc) / w);
  }
  if (dt > T) dist += g.v1 * (dt - T);
}
}  // namespace

Trajectory::Trajectory(const Scenario& s) : Trajectory(s.trajectory, Vibration(s.vibration, s.seed)) {}

Trajectory::Trajectory(const TrajectorySpec& spec, Vibration vibration)
    : segs_(spec.segments), z_(spec.z), vib_(vibration) {
  Start s{0, spec.x0, spec.y0, spec.heading0_deg * kPi / 180.0};
  for (const auto& g : segs_) {
    starts_.push_back(s);
    const BodyState e = advance(g, s, g.duration_s, z_);
    s = Start{s.t + g.duration_s, e.x, e.y, e.heading};
  }
}

BodyState Trajectory::advance(const SegmentSpec& g, const Start& s, double dt, double z) {
  double dist = 0, v = 0, a = 0;
  profile(g, dt, dist, v, a);
  BodyState b;
  b.z = z;
  b.speed = v;
  b.accel = a;
  b.curvature = g.curvature;
  b.yaw_rate = v * g.curvature;
  const double k = g.curvature;
  const double dh = k * dist;
  b.heading = s.heading + dh;
  if (std::fabs(dh) < 1e-9) {
    // Straight (or nearly): second-order expansion avoids dividing by k.
    b.x = s.x + dist * (std::cos(s.heading) - 0.5 * dh * std::sin(s.heading));
    b.y = s.y + dist * (std::sin(s.heading) + 0.5 * dh * std::cos(s.heading));
  } else {
    b.x = s.x + (std::sin(b.heading) - std::sin(s.heading)) / k;
    b.y = s.y - (std::cos(b.heading) - std::cos(s.heading)) / k;
  }
  return b;
}

BodyState Trajectory::at(double t) const {
  size_t i = 0;
  while (i + 1 < starts_.size() && t >= starts_[i + 1].t) ++i;
  BodyState b = advance(segs_[i], starts_[i], t - starts_[i].t, z_);
  // Untouched without vibration: a level body's states stay bit for bit.
  if (vib_.none()) return b;
  const VibrationState v = vib_.at(t);
  b.z += v.heave;
  b.vz = v.heave_rate;
  b.az = v.heave_accel;
  b.pitch = v.pitch;
  b.roll = v.roll;
  b.pitch_rate = v.pitch_rate;
  b.roll_rate = v.roll_rate;
  return b;
}

}  // namespace lumavel::host::render
