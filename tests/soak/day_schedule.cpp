#include "day_schedule.hpp"

#include <cmath>

#include "lumavel/host/settings.hpp"

namespace lumavel::soak {

namespace {

constexpr double kAccel = 1.0;                 // m/s^2, speeding up and slowing down
constexpr double kBurstsPerFrame = 300.0 / (86400 * 60);
constexpr double kDropPerFrame = 0.002;
constexpr double kGyroNoise = 0.002;           // rad/s rms per sample
constexpr auto kGyroPeriodNs = static_cast<uint64_t>(1e9 / DaySchedule::kGyroHz);

}  // namespace

DaySchedule::DaySchedule(uint64_t seed) : rng_(seed * 2685821657736338717ull + 1) {}

double DaySchedule::uniform() {
  rng_ ^= rng_ >> 12;
  rng_ ^= rng_ << 25;
  rng_ ^= rng_ >> 27;
  return static_cast<double>((rng_ * 2685821657736338717ull) >> 11) / 9007199254740992.0;
}

double DaySchedule::offset_at(uint64_t t_ns) const {
  // 1 deg/s, drifting by +-0.002 rad/s over 6 h (temperature).
  return 0.0175 + 0.002 * std::sin(2 * 3.14159265358979323846 * static_cast<double>(t_ns) * 1e-9 / 21600);
}

uint64_t DaySchedule::frame_time(uint64_t i) {
  return static_cast<uint64_t>(std::llround(static_cast<double>(i) * 1e9 / kFps));
}

void DaySchedule::next_phase() {
  auto drive = [this] {
    phase_ = Phase::kDrive;
    phase_left_ = 40 + 260 * uniform();
    target_ = direction_ * (0.2 + 2.8 * uniform());
    retarget_in_ = 5 + 55 * uniform();
  };
  switch (phase_) {
    case Phase::kDrive:
      if (uniform() < 0.35) {  // reversal: through zero without stopping
        direction_ = -direction_;
        ++counts_.reversals;
        drive();
      } else {
        phase_ = Phase::kStop;
        target_ = 0;
      }
      break;
    case Phase::kStop: {
      phase_ = Phase::kStill;
      const bool brief = uniform() < 0.15;
      phase_left_ = brief ? 0.1 + 0.35 * uniform() : 1 + 29 * uniform();
      ++counts_.standstills;
      if (brief) ++counts_.short_standstills;
      break;
    }
    case Phase::kStill:
      if (uniform() < 0.2) {
        direction_ = -direction_;
        ++counts_.reversals;
      }
      drive();
      break;
  }
}

void DaySchedule::step(double dt) {
  double a = (target_ - v_) / dt;
  if (a > kAccel) a = kAccel;
  if (a < -kAccel) a = -kAccel;
  s0_ = s_;
  v0_ = v_;
  travelled0_ = travelled_;
  a_ = a;
  const double ds = v_ * dt + a * dt * dt / 2;
  s_ += ds;
  travelled_ += std::fabs(ds);
  v_ += a * dt;
  if (std::fabs(v_ - target_) < 1e-12) v_ = target_;
  switch (phase_) {
    case Phase::kDrive:
      phase_left_ -= dt;
      retarget_in_ -= dt;
      if (retarget_in_ <= 0) {
        target_ = direction_ * (0.2 + 2.8 * uniform());
        retarget_in_ = 5 + 55 * uniform();
      }
      if (phase_left_ <= 0) next_phase();
      break;
    case Phase::kStop:
      if (v_ == 0) next_phase();
      break;
    case Phase::kStill:
      phase_left_ -= dt;
      if (phase_left_ <= 0) next_phase();
      break;
  }
}

GyroSample DaySchedule::next_gyro() {
  const uint64_t t = gyro_k_ * kGyroPeriodNs;
  if (gyro_k_ > 0) step(static_cast<double>(kGyroPeriodNs) * 1e-9);
  ++gyro_k_;
  t0_ = t_;
  t_ = t;
  // Box-Muller from two uniforms: the noise of one sample.
  const double u1 = uniform() + 1e-300, u2 = uniform();
  const double n = std::sqrt(-2 * std::log(u1)) * std::cos(2 * 3.14159265358979323846 * u2);
  const double rate = v_ / kPathRadius + offset_at(t) + kGyroNoise * n;
  return {t, host::to_fixed_rate(rate)};
}

bool DaySchedule::frame_delivered(uint64_t) {
  if (burst_left_ > 0) {
    --burst_left_;
    return false;
  }
  if (uniform() < kBurstsPerFrame) {
    burst_left_ = 34 + static_cast<int>(30 * uniform());  // 35..64 frames with this one
    ++counts_.bursts;
    return false;
  }
  if (uniform() < kDropPerFrame) {
    ++counts_.dropped;
    return false;
  }
  return true;
}

DaySchedule::State DaySchedule::at(uint64_t t_ns) const {
  if (t_ns >= t_ || t_ == t0_) return {s_, v_, travelled_};
  const double tau = t_ns > t0_ ? static_cast<double>(t_ns - t0_) * 1e-9 : 0;
  const double ds = v0_ * tau + a_ * tau * tau / 2;
  return {s0_ + ds, v0_ + a_ * tau, travelled0_ + std::fabs(ds)};
}

}  // namespace lumavel::soak
