// A barrel-distorted lens for the synthetic test stream: the directions the
// renderer sees through it, and the lens tables (report 0x05 pieces) that
// tell the device about it. Host-only (double precision).
#pragma once
#include <cstdint>
#include <vector>

#include "lumavel/core/config.hpp"
#include "lumavel/core/fixed.hpp"
#include "lumavel/protocol/device_config.hpp"

namespace lumavel::stream {

// Radial distortion x_d = x (1 + k1 x^2) of the normalised column coordinate
// x = tan(angle off the axis); k1 < 0 is barrel. One k1 per camera, different
// so that the two tables differ.
constexpr double kBarrelK1[2] = {-0.14, -0.10};

// The undistorted x whose distorted image is xd (host::LensDistortion with
// k1 only; it settles for |k1| xd^2 well below 1, as in a 60 degree view).
double undistort(double xd, double k1);

// Per-edge corrections to the device's pinhole edges of camera g (its
// quantised geometry), u = 0..width: the edge through the lens minus the
// pinhole edge the firmware computes (host::lens_table), rounded to Q15.
std::vector<EdgeOffsetQ15> barrel_edge_offsets(const CameraGeometry& g, uint16_t width, double k1);

// The set-feature reports that upload both tables (0x05 pieces, camera 0
// first, width + 1 edges each) and then the configuration c with its lens
// bits and lens_crc naming them.
std::vector<std::vector<uint8_t>> lens_upload_reports(protocol::DeviceConfig c,
                                                      const std::vector<EdgeOffsetQ15> (&tables)[2]);

}  // namespace lumavel::stream
