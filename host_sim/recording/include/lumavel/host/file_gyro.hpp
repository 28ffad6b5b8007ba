// hal::Gyro over a recording's imu0: yaw rate about body z, (R_BS * w_S).z,
// converted to RateQ24 (Q7.24, rounded, saturated) like a board driver.
#pragma once
#include <cstddef>

#include "lumavel/hal/gyro.hpp"
#include "lumavel/host/recording.hpp"

namespace lumavel::host {

// rad/s to Q7.24: round half away from zero, saturate to [-128, 128).
RateQ24 rate_to_q24(double rad_s);

class FileGyro : public hal::Gyro {
 public:
  explicit FileGyro(const Recording& rec) : rec_(rec) {}  // rec must outlive the gyro
  bool read(hal::GyroSample& out) override;

 private:
  const Recording& rec_;
  size_t next_ = 0;
};

}  // namespace lumavel::host
