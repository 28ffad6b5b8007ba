#include "lumavel/host/file_gyro.hpp"

#include "lumavel/units/si.hpp"

namespace lumavel::host {

RateQ24 rate_to_q24(double rad_s) { return si::Rate::from_si(rad_s); }  // NaN: never in a loaded recording

bool FileGyro::read(hal::GyroSample& out) {
  if (next_ >= rec_.imu_samples.size()) return false;
  const ImuSample& s = rec_.imu_samples[next_++];
  out.t_ns = s.t_ns;
  out.rate_z = rate_to_q24(body_yaw_rate(rec_.imu, s));
  return true;
}

}  // namespace lumavel::host
