#include "lumavel/host/file_gyro.hpp"

#include <cmath>

namespace lumavel::host {

RateQ24 rate_to_q24(double rad_s) {
  const double scaled = std::round(rad_s * static_cast<double>(1 << fx::kRateFrac));  // half away from zero
  if (!(scaled < 2147483647.0)) return fx::kInt32Max;  // also catches NaN (never in a loaded recording)
  if (scaled < -2147483648.0) return fx::kInt32Min;
  return static_cast<RateQ24>(scaled);
}

bool FileGyro::read(hal::GyroSample& out) {
  if (next_ >= rec_.imu_samples.size()) return false;
  const ImuSample& s = rec_.imu_samples[next_++];
  out.t_ns = s.t_ns;
  out.rate_z = rate_to_q24(body_yaw_rate(rec_.imu, s));
  return true;
}

}  // namespace lumavel::host
