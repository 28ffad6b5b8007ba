// The double-precision reference engine: the firmware core's estimator
// (firmware/core/estimator.hpp) with no quantisation, on Eigen vectors, laid
// out file for file like the core (float_column_profile, float_kernel_bank,
// float_measurement, float_velocity_observer, float_gyro_integrator,
// float_gyro_offset, float_time_of_flight, float_velocity_fusion,
// float_photometric_balance, float_photometric_match). Used to bound the fixed-point error and as
// `--engine float`.
#pragma once
#include <cstdint>

#include "lumavel/host/engine.hpp"
#include "lumavel/host/float_gyro_integrator.hpp"
#include "lumavel/host/float_gyro_offset.hpp"
#include "lumavel/host/float_image_direction.hpp"
#include "lumavel/host/float_kernel_bank.hpp"
#include "lumavel/host/float_measurement.hpp"
#include "lumavel/host/float_photometric_balance.hpp"
#include "lumavel/host/float_photometric_match.hpp"
#include "lumavel/host/float_time_of_flight.hpp"
#include "lumavel/host/float_velocity_fusion.hpp"
#include "lumavel/host/float_velocity_observer.hpp"
#include "lumavel/host/settings.hpp"

namespace lumavel::host {

class FloatEstimator {
 public:
  explicit FloatEstimator(const EstimatorSettings& s);
  void push_gyro(uint64_t t_ns, double rate) { gyro_.push(t_ns, rate); }
  EngineEstimate step(uint64_t t_ns, const uint8_t* cam0, const uint8_t* cam1);
  const FloatKernelBank& bank() const { return bank_; }

 private:
  EstimatorSettings s_;
  FloatKernelBank bank_;
  FloatGyroIntegrator gyro_;
  FloatGyroOffset gyro_offset_;
  FloatVelocityObserver observer_;
  FloatTimeOfFlight tof_;
  FloatImageDirection direction_;
  int look_ = 0;
  FloatPhotometricBalance balance_;
  FloatPhotometricMatch match_;
  FloatVelocityFusion fusion_;
  double tof_max_rotation_ = 0;  // rotation allowed between the two sightings, rad
  double match_max_rotation_ = 0;  // ... of a photometric match's sample, rad
  double scale_max_turn_ = 0;      // ... weighing a scale measurement as its limit, rad
  double y_ = 0;                 // integral of the differential observer's direct values, m
  FloatStereoMeasurement prev_;  // the previous frame's
  Eigen::MatrixXd jac_;          // cam1's dF/dp, held for one frame after it was formed (as the core)
  bool jac_held_ = false;
  bool have_prev_ = false;
  uint64_t prev_t_ns_ = 0;
  double prev_gyro_angle_ = 0;  // raw integral, unwrapped, rad
  double heading_ = 0;          // offset-corrected integral, unwrapped, rad
  bool have_prev_frame_ = false;  // a frame was stepped since the start
  double distance_ = 0;
  // The configuration's timing, whole microseconds as the core has it, in ns,
  // so that both engines flag on the same frames even at a tie.
  uint64_t gyro_gap_ns_ = 0, frame_period_ns_ = 0, max_gap_ns_ = 0, still_min_ns_ = 0;
};

}  // namespace lumavel::host
