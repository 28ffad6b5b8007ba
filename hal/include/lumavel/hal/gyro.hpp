// Yaw-rate gyro: samples in time order, at the sensor's own rate.
#pragma once
#include <cstdint>

#include "lumavel/units/fixed.hpp"

namespace lumavel::hal {

struct GyroSample {
  uint64_t t_ns;
  RateQ24 rate_z;  // body z (yaw), rad/s, CCW seen from above positive
};

class Gyro {
 public:
  virtual ~Gyro() = default;
  // The next sample if one is ready (non-blocking); false otherwise.
  virtual bool read(GyroSample& out) = 0;
};

}  // namespace lumavel::hal
