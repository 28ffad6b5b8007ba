// Twin of firmware/core/include/lumavel/core/image_direction.hpp: the
// direction of travel from each camera's own image motion.
#pragma once

#include "lumavel/host/float_measurement.hpp"
#include "lumavel/host/settings.hpp"

namespace lumavel::host {

class FloatImageDirection {
 public:
  void reset() { *this = FloatImageDirection{}; }
  void update(const FloatStereoMeasurement& prev, const FloatStereoMeasurement& cur, double dtheta, double dt_ns,
              int look);
  int direction() const { return direction_; }  // +1 along +x, -1 along -x, 0 unknown
  bool against(double v) const;                   // (the core's)

 private:
  double mean_ = 0, var_ = 0;  // rad/s signed as V; (rad/s)^2
  int direction_ = 0;
};

// The core's image_look(): +1 looking left, -1 right, 0 near the travel.
int float_image_look(const CameraModel& cam0, const CameraModel& cam1);

}  // namespace lumavel::host
