// The double-precision reference engine: the firmware core's mathematics
// (kernel_bank, measurement, velocity_observer, gyro_integrator) with no
// quantisation, on Eigen vectors. Used to bound the fixed-point error and as
// `--engine float`.
#pragma once
#include <cstdint>

#include "lumavel/host/engine.hpp"
#include "lumavel/host/float_kernel_bank.hpp"
#include "lumavel/host/float_measurement.hpp"
#include "lumavel/host/float_photometric_balance.hpp"
#include "lumavel/host/float_time_of_flight.hpp"
#include "lumavel/host/float_velocity_fusion.hpp"
#include "lumavel/host/settings.hpp"

namespace lumavel::host {

class FloatEstimator {
 public:
  explicit FloatEstimator(const EstimatorSettings& s);
  void push_gyro(uint64_t t_ns, double rate);
  EngineEstimate step(uint64_t t_ns, const uint8_t* cam0, const uint8_t* cam1);
  const FloatKernelBank& bank() const { return bank_; }

 private:
  double angle_at(uint64_t t_ns) const;
  bool gyro_covers(uint64_t from_ns, uint64_t to_ns) const;  // GyroIntegrator::covers
  bool gyro_saturated_since(uint64_t from_ns) const;          // GyroIntegrator::saturated_since
  void learn_offset(const FloatStereoMeasurement& m, uint64_t t_ns, double angle, bool textured);

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
  FloatKernelBank bank_;
  Gyro gyro_;
  uint64_t gyro_gap_ns_ = 0;    // the configuration's timing, whole microseconds as the core has it
  uint64_t frame_period_ns_ = 0, max_gap_ns_ = 0, converging_ns_ = 0, still_min_ns_ = 0;
  // observer
  FloatStereoMeasurement prev_;
  bool have_prev_ = false, started_ = false;
  double v_ = 0, distance_ = 0, prev_gyro_angle_ = 0;
  uint64_t since_start_ns_ = 0;
  uint64_t prev_t_ns_ = 0;
  // gyro offset learning and the corrected heading
  double offset_ = 0, heading_ = 0, angle_ref_ = 0;
  bool have_prev_frame_ = false;
  uint64_t t_ref_ = 0;
  FloatStereoMeasurement ref_;
  bool have_ref_ = false, still_ = false;
  // time of flight and fusion
  FloatTimeOfFlight tof_;
  FloatVelocityFusion fusion_;
  FloatPhotometricBalance balance_;
  double tof_max_rotation_ = 0;
  double y_ = 0;
};

}  // namespace lumavel::host
