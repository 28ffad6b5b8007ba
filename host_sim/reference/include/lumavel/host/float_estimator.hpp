// The double-precision reference engine: the firmware core's mathematics
// (kernel_bank, measurement, velocity_observer, gyro_integrator) with no
// quantisation, on Eigen vectors. Used to bound the fixed-point error and as
// `--engine float`.
#pragma once
#include <Eigen/Dense>
#include <cstdint>
#include <vector>

#include "lumavel/host/engine.hpp"
#include "lumavel/host/float_column_band.hpp"
#include "lumavel/host/float_photometric_balance.hpp"
#include "lumavel/host/float_time_of_flight.hpp"
#include "lumavel/host/float_velocity_fusion.hpp"
#include "lumavel/host/settings.hpp"

namespace lumavel::host {

struct FloatKernels {
  Eigen::VectorXd norm, norm_d;
  Eigen::VectorXd dc;  // F of a uniform image, per kernel (sum K / sum N)
  std::vector<Eigen::VectorXd> k, d, t;  // B, dB/dtheta, d3B/dtheta3 kernels
};

// Tables of both cameras, built exactly as build_kernel_bank does.
struct FloatBank {
  FloatKernels cam[2];
  Eigen::VectorXd edge[2];  // column edge yaws, width + 1
  FloatColumnBand band;     // the rows each column sums, the tables' cos(a_u) weight
};
FloatBank build_float_bank(const EstimatorSettings& s);

struct FloatMeasurement {
  Eigen::VectorXd mid, diff, rot;
  Eigen::VectorXd half_phase;            // x = k h / 2 per kernel, from the cameras' phases
  Eigen::VectorXd f[2], r[2];            // each camera's F and dF/dtheta
  Eigen::VectorXd balance;               // the photometric offset subtracted from cam1's F
  bool no_light = false;
  bool no_stereo = false;  // same textured column profile in both cameras (same_textured_profile)
  double clipped = 0, sampled = 0;
};

// Both cameras' normalised kernel outputs for one frame pair (the twin of
// column_profile + stereo_measurement), cam1's corrected by the balance when
// one is given.
FloatMeasurement measure_float(const FloatBank& bank, const EstimatorSettings& s,
                               const uint8_t* cam0, const uint8_t* cam1,
                               const FloatPhotometricBalance* balance = nullptr);

class FloatEstimator {
 public:
  explicit FloatEstimator(const EstimatorSettings& s);
  void push_gyro(uint64_t t_ns, double rate);
  EngineEstimate step(uint64_t t_ns, const uint8_t* cam0, const uint8_t* cam1);
  const FloatBank& bank() const { return bank_; }

 private:
  double angle_at(uint64_t t_ns) const;
  bool gyro_covers(uint64_t from_ns, uint64_t to_ns) const;  // GyroIntegrator::covers
  bool gyro_saturated_since(uint64_t from_ns) const;          // GyroIntegrator::saturated_since
  void learn_offset(const FloatMeasurement& m, uint64_t t_ns, double angle, bool textured);

  // The gyro as GyroIntegrator keeps it: the last two samples ([1] the newer)
  // and the integrated angle at each, with the core's member names.
  struct Gyro {
    uint64_t t[2]{};              // sample times, ns
    double r[2]{};                // rates, rad/s (clipped to the core's RateQ24 range)
    double angle[2]{};            // integrated angle at each sample, rad
    bool at_rail[2]{};            // the sample was clipped to that range
    int count = 0;                // samples since the start
    uint64_t t_first = 0;         // first sample since the start
    bool railed = false;          // a trapezoid has had a clipped end ...
    uint64_t railed_end = 0;      // ... ending here
    uint64_t max_spacing = 0;     // longest sample spacing since the last frame, ns
  };

  EstimatorSettings s_;
  FloatBank bank_;
  Gyro gyro_;
  uint64_t gyro_gap_ns_ = 0;    // the configuration's timing, whole microseconds as the core has it
  uint64_t frame_period_ns_ = 0, max_gap_ns_ = 0, converging_ns_ = 0, still_min_ns_ = 0;
  // observer
  FloatMeasurement prev_;
  bool have_prev_ = false, started_ = false;
  double v_ = 0, distance_ = 0, prev_gyro_angle_ = 0;
  uint64_t since_start_ns_ = 0;
  uint64_t prev_t_ns_ = 0;
  // gyro offset learning and the corrected heading
  double offset_ = 0, heading_ = 0, angle_ref_ = 0;
  bool have_prev_frame_ = false;
  uint64_t t_ref_ = 0;
  FloatMeasurement ref_;
  bool have_ref_ = false, still_ = false;
  // time of flight and fusion
  FloatTimeOfFlight tof_;
  FloatVelocityFusion fusion_;
  FloatPhotometricBalance balance_;
  double tof_max_rotation_ = 0;
  double y_ = 0;
};

}  // namespace lumavel::host
