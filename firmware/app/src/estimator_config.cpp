#include "lumavel/app/estimator_config.hpp"

namespace lumavel::app {

using namespace protocol;

namespace {
constexpr AngleQ28 kHalfPi = 421657428;  // pi/2
}  // namespace

bool to_estimator_config(const DeviceConfig& c, EstimatorConfig& out, const EdgeOffsetQ15* const lens[2]) {
  if (validate(c) != ConfigField::kOk) return false;
  for (int i = 0; i < 2; ++i)
    if ((c.lens & (1u << i)) != 0 && (lens == nullptr || lens[i] == nullptr)) return false;
  EstimatorConfig e{};
  e.width = c.width;
  e.height = c.height;
  const AngleQ28 axis0 = (c.orientation & kLooksRight) ? -kHalfPi : kHalfPi;
  const uint8_t upside[2] = {kCam0UpsideDown, kCam1UpsideDown};
  for (int i = 0; i < 2; ++i) {
    e.cam[i].fu = c.fu[i];
    e.cam[i].cu = c.cu[i];
    e.cam[i].axis_yaw = i == 0 ? axis0 : axis0 + c.misalignment;
    e.cam[i].u_sign = (c.orientation & upside[i]) ? int8_t{1} : int8_t{-1};
  }
  e.baseline = c.baseline;
  e.normaliser = KernelSpec{0, c.normaliser_sigma};
  for (int i = 0; i < c.kernel_count; ++i) {
    e.kernels[i] = KernelSpec{c.kernels[i].order, c.kernels[i].sigma};
  }
  e.kernel_count = c.kernel_count;
  e.tau_us = c.tau_us;
  e.frame_period_us = c.frame_period_us;
  e.max_gap_us = c.max_gap_us;
  e.gyro_gap_us = c.gyro_gap_us;
  e.low_texture = c.low_texture;
  e.saturated_permille = c.saturated_permille;
  e.options = c.options;
  e.still_distance = c.still_distance;
  e.still_min_us = c.still_min_us;
  for (int i = 0; i < 2; ++i) e.edge_offsets[i] = (c.lens & (1u << i)) != 0 ? lens[i] : nullptr;
  out = e;
  return true;
}

}  // namespace lumavel::app
