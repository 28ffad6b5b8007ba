// The estimator: a stereo pair of working-resolution frames and the gyro in,
// the curvilinear velocity V (and s, heading, status) out. Fixed memory,
// integer only, no I/O.
#pragma once
#include <cstdint>

#include "lumavel/core/column_profile.hpp"
#include "lumavel/core/config.hpp"
#include "lumavel/core/gyro_integrator.hpp"
#include "lumavel/core/gyro_offset.hpp"
#include "lumavel/core/image_direction.hpp"
#include "lumavel/core/kernel_bank.hpp"
#include "lumavel/core/measurement.hpp"
#include "lumavel/core/photometric_match.hpp"
#include "lumavel/core/time_of_flight.hpp"
#include "lumavel/core/velocity_fusion.hpp"
#include "lumavel/core/velocity_observer.hpp"

namespace lumavel {

// Two 8-bit frames at the configured working resolution, taken together.
struct FramePair {
  uint64_t t_ns;          // middle of the exposure
  const uint8_t* cam[2];  // row-major, `stride` bytes between rows
  uint16_t stride;
};

struct Estimate {
  uint64_t t_ns;
  uint32_t frame_index;
  SpeedQ16 v;          // curvilinear velocity: the differential and the time of flight fused
  DistQ32 distance;    // integral of v
  AngleQ28 heading;    // integral of the gyro, wrapped to [-pi, pi)
  uint16_t status;     // StatusFlag bits
  SpeedQ16 v_direct;   // this interval's direct measurement (0 when none)
  ValueQ28 texture;    // rms over kernels of F1 - F0, weaker frame of the interval
  RateQ24 gyro_offset; // learned zero-rate offset, subtracted from the gyro
  SpeedQ16 v_differential;  // the differential observer alone (paper eq. 9)
  int64_t tof_ns;      // this frame's time of flight (0: none)
  ScaleQ24 scale;      // the differential's learned scale against the time of flight
  bool outvoted;       // the differential pointed against the time of flight and was outvoted
                       // (velocity_fusion.hpp: a decision on a continuous margin, as NO_TOF is)
};

class Estimator {
 public:
  // Validates, builds the kernel tables and resets. On error the estimator
  // keeps its previous configuration.
  ConfigError configure(const EstimatorConfig& cfg);
  void reset();

  // Gyro samples in time order. Before step(t) push every sample up to the
  // first one at or after t when the sensor has it (interpolation needs it).
  void push_gyro(uint64_t t_ns, RateQ24 rate_z) { gyro_.push(t_ns, rate_z); }

  Estimate step(const FramePair& frames);
  // The same step from both cameras' column profiles, taken by the caller
  // (column_profile, or ColumnStream as the rows arrive: no frame buffers);
  // they must be of the configured width and height and band (bank().
  // column_band()). step(frames) is column_profile then this. cam1's profile
  // is mapped in place by the photometric match, with the rows' share of the
  // vignetting where cam1's radial sums are given (taken with cam1_rings()).
  Estimate step_profiles(uint64_t t_ns, ColumnProfile& p0, ColumnProfile& p1, const RadialSums* radial1 = nullptr);
  // The rings cam1's radial sums are taken with (nullptr: none: no match,
  // a band, a line scan), as step() takes them.
  const RadialRings* cam1_rings() const {
    return (cfg_.options & kOptionPhotometricMatch) ? bank_.radial_rings() : nullptr;
  }

  const EstimatorConfig& config() const { return cfg_; }
  const KernelBank& bank() const { return bank_; }
  // The photometric match's mapping in use (Q30: a1, a2, beta in 64 DN;
  // photometric_match.hpp); all 0 where it is not built in or not learned.
  void photometric_params(int32_t out[kMatchParams]) const {
    for (int j = 0; j < kMatchParams; ++j) out[j] = 0;
#if LUMAVEL_MATCH_FRAMES > 0
    for (int j = 0; j < kMatchParams; ++j) out[j] = match_.params()[j];
#endif
  }
  // The index the next frame gets (tests: the wrap at 2^32, 2.3 years at
  // 60 Hz, 50 days at 1 kHz, must change nothing but the index).
  void set_next_frame_index(uint32_t index) { frame_index_ = index; }

 private:
  EstimatorConfig cfg_{};
  KernelBank bank_{};
  GyroIntegrator gyro_{};
  GyroOffset gyro_offset_{};
  VelocityObserver observer_{};
  TimeOfFlight tof_{};
  ImageDirection direction_{};
  int8_t look_ = 0;  // image_look() of the cameras
  PhotometricBalance balance_{};
#if LUMAVEL_MATCH_FRAMES > 0
  PhotometricMatch match_{};
#endif
  VelocityFusion fusion_{};
  AngleQ28 tof_max_rotation_ = 0;  // rotation allowed between the two sightings
  AngleQ28 match_max_rotation_ = 0;  // ... of a photometric match's sample
  AngleQ28 scale_max_turn_ = 0;     // ... weighing a scale measurement as its limit (fusion_params.hpp)
  TravelQ16Ns y_ = 0;              // integral of the differential observer's direct values
  StereoMeasurement meas_[2]{};  // previous and current frame
#if LUMAVEL_MATCH_FRAMES > 0
  MatchJac jac_{};               // cam1's dF/dp, held for one frame after it was formed
  bool jac_held_ = false;        // jac_ was formed on the frame before: this one takes it as it is
#endif
  int cur_ = 0;
  bool have_prev_ = false;
  bool configured_ = false;
  uint64_t prev_t_ns_ = 0;
  int64_t prev_gyro_angle_ = 0;  // raw integral, unwrapped, Q3.28
  int64_t heading_ = 0;          // offset-corrected integral, unwrapped, Q3.28
  uint32_t frame_index_ = 0;    // wraps at 2^32: never a state
  bool have_prev_frame_ = false;  // a frame was stepped since the reset
  DistQ32 distance_ = 0;
  int64_t distance_rem_ = 0;  // carried remainder of the distance integral, [0, 1e9)
};

}  // namespace lumavel
