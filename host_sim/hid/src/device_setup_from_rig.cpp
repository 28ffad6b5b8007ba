#include "lumavel/host/device_setup_from_rig.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "lumavel/app/estimator_config.hpp"
#include "lumavel/core/fixed.hpp"

namespace lumavel::host {
namespace {

namespace proto = lumavel::protocol;

constexpr double kHalfPi = 1.57079632679489661923;

// The same camera turned by `yaw` (its edge table with it).
CameraModel rotated(CameraModel c, double yaw) {
  c.axis_yaw += yaw;
  for (double& e : c.edges) e += yaw;
  return c;
}

}  // namespace

DeviceSetup device_setup_from_settings(const EstimatorSettings& in) {
  // Rotate the rig so that cam0 looks exactly to one side.
  const bool right = in.cam[0].axis_yaw < 0;
  const double turn = (right ? -kHalfPi : kHalfPi) - in.cam[0].axis_yaw;
  EstimatorSettings s = in;
  for (CameraModel& c : s.cam) c = rotated(c, turn);
  const EstimatorConfig e = to_fixed_config(s);  // quantised and checked by the core

  DeviceSetup out{};
  proto::DeviceConfig& d = out.config;
  d.width = e.width;
  d.height = e.height;
  d.baseline = e.baseline;
  d.misalignment = e.cam[1].axis_yaw - e.cam[0].axis_yaw;
  d.orientation = static_cast<uint8_t>((right ? proto::kLooksRight : 0) |
                                       (e.cam[0].u_sign > 0 ? proto::kCam0UpsideDown : 0) |
                                       (e.cam[1].u_sign > 0 ? proto::kCam1UpsideDown : 0));
  for (int i = 0; i < 2; ++i) {
    d.fu[i] = e.cam[i].fu;
    d.cu[i] = e.cam[i].cu;
  }
  d.normaliser_sigma = e.normaliser.sigma;
  if (e.kernel_count > proto::kWireKernels)
    throw std::invalid_argument(std::to_string(e.kernel_count) + " kernels: the HID configuration carries at most " +
                                std::to_string(proto::kWireKernels));
  d.kernel_count = e.kernel_count;
  for (int k = 0; k < e.kernel_count; ++k) d.kernels[k] = proto::KernelSetting{e.kernels[k].order, e.kernels[k].sigma};
  d.tau_us = e.tau_us;
  d.frame_period_us = e.frame_period_us;
  d.max_gap_us = e.max_gap_us;
  d.gyro_gap_us = e.gyro_gap_us;
  d.low_texture = e.low_texture;
  d.saturated_permille = e.saturated_permille;
  d.options = e.options;
  d.still_distance = e.still_distance;
  d.still_min_us = e.still_min_us;

  // The device rebuilds cam i's geometry from d (to_estimator_config): the
  // lens corrections are taken against exactly that geometry.
  EstimatorConfig dev{};
  d.lens = 0;
  d.lens_crc = 0;
  const proto::ConfigField f = proto::validate(d);
  if (f != proto::ConfigField::kOk || !app::to_estimator_config(d, dev))
    throw std::invalid_argument(std::string("the rig's ") + proto::to_string(f) +
                                " is outside what the HID configuration accepts (docs/usb-hid.md)");
  for (int i = 0; i < 2; ++i) out.lens[i] = to_fixed_edge_offsets(s.cam[i], dev.cam[i], s.width);
  seal_lens(out);
  return out;
}

DeviceSetup device_setup_from_recording(const Recording& rec, WorkingSize size, double misalignment_rad) {
  EstimatorSettings s = derive_settings(rec, size);
  if (std::isfinite(misalignment_rad)) {
    const double now = s.cam[1].axis_yaw - s.cam[0].axis_yaw;
    s.cam[1] = rotated(s.cam[1], misalignment_rad - now);
  }
  return device_setup_from_settings(s);
}

}  // namespace lumavel::host
