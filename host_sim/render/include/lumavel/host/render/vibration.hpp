// Rig vibration as a function of time: pitch, roll and heave, each a sum of
// kVibrationTones sinusoids at frequencies spread over the scenario's band
// (geometric strata, one tone in each at a seeded place) with seeded phases,
// so the motion is smooth, analytic (rates and heave acceleration exact for
// the gyro, accelerometer and ground truth) and deterministic per seed.
#pragma once
#include <array>
#include <cstdint>

#include "lumavel/host/render/scenario.hpp"

namespace lumavel::host::render {

constexpr int kVibrationTones = 4;

struct VibrationState {
  double pitch = 0, roll = 0, heave = 0;  // rad, rad, m
  double pitch_rate = 0, roll_rate = 0, heave_rate = 0;  // rad/s, rad/s, m/s
  double heave_accel = 0;  // m/s^2
};

class Vibration {
 public:
  Vibration() = default;  // none: at() is all zeros
  Vibration(const VibrationSpec& spec, uint64_t seed);
  bool none() const { return none_; }
  VibrationState at(double t) const;

 private:
  struct Tone {
    double amplitude = 0, omega = 0, phase = 0;  // sin(omega t + phase)
  };
  using Axis = std::array<Tone, kVibrationTones>;
  // value, first and second derivative of the axis at t
  static void eval(const Axis& a, double t, double& v, double& dv, double& ddv);
  bool none_ = true;
  Axis pitch_{}, roll_{}, heave_{};
};

}  // namespace lumavel::host::render
