// The truth of the soak's simulated day, generated as it runs (nothing is
// stored per frame): the rig's motion on its circle (speeds 0.2-3 m/s,
// accelerations of 1 m/s^2, reversals, standstills, some too short to learn
// from), the gyro (200 Hz, white noise and a slowly drifting zero-rate
// offset, quantised as the firmware takes it), and which 60 Hz frames are
// delivered (single drops and 35-64-frame gap bursts). Deterministic.
#pragma once
#include <cstdint>

#include "lumavel/core/fixed.hpp"

namespace lumavel::soak {

struct GyroSample {
  uint64_t t_ns;
  RateQ24 rate;  // as the firmware takes it (host::to_fixed_rate)
};

struct DayCounts {
  int reversals = 0, standstills = 0, short_standstills = 0;  // short: under still_min, nothing to learn
  int dropped = 0, bursts = 0;
};

class DaySchedule {
 public:
  static constexpr double kFps = 60;
  static constexpr double kGyroHz = 200;
  static constexpr double kPathRadius = 20;  // m: the scene is given the same (PillarScene::path_radius)

  explicit DaySchedule(uint64_t seed);

  // The gyro samples in time order; each moves the truth on to its time.
  GyroSample next_gyro();

  // The truth at t, which must lie between the last two gyro samples (the
  // push contract has the sample at or after a frame pushed before it).
  struct State {
    double s;          // arc position, m (CCW positive)
    double v;          // velocity along body x, m/s
    double travelled;  // path length since the start, m
  };
  State at(uint64_t t_ns) const;
  double offset_at(uint64_t t_ns) const;  // the gyro's true zero-rate offset, rad/s

  // Whether frame i (at round(i * 1e9 / 60) ns) is delivered.
  bool frame_delivered(uint64_t i);
  static uint64_t frame_time(uint64_t i);

  const DayCounts& counts() const { return counts_; }

 private:
  double uniform();  // [0, 1)
  void next_phase();
  void step(double dt);  // dt s of motion under the current target

  uint64_t rng_;
  uint64_t t_ = 0;  // truth time (the last gyro sample), ns
  double s_ = 0, v_ = 0, travelled_ = 0;
  // The step that led to t_: its start and its constant acceleration.
  uint64_t t0_ = 0;
  double s0_ = 0, v0_ = 0, travelled0_ = 0, a_ = 0;
  double target_ = 0;  // speed the rig is ramping to
  enum class Phase { kDrive, kStop, kStill } phase_ = Phase::kStill;
  double phase_left_ = 2;   // s left in the phase (kDrive, kStill)
  double retarget_in_ = 0;  // s until the next speed change while driving
  double direction_ = 1;
  uint64_t gyro_k_ = 0;
  int burst_left_ = 0;
  DayCounts counts_;
};

}  // namespace lumavel::soak
