// The device configuration built from a rig's settings: the device, rebuilding
// its geometry from it, must see the same column edges as the host's engine.
#include <CppUTest/TestHarness.h>

#include <cmath>
#include <stdexcept>

#include "lumavel/app/estimator_config.hpp"
#include "lumavel/core/kernel_bank.hpp"
#include "lumavel/host/device_setup_from_rig.hpp"
#include "recording_fixture.hpp"

using namespace lumavel;
using lumavel::host::load_recording;
using lumavel::host::Recording;

namespace {

// A 40-column, 60 degree rig looking right (cam1 upside down), turned by a
// yaw common to both cameras, with barrel distortion on cam0.
host::EstimatorSettings rig(double misalignment) {
  host::EstimatorSettings s;
  s.width = 40;
  s.height = 30;
  s.baseline = -0.07;
  const double turn = 0.03, fu = 20 / std::tan(M_PI / 6);
  for (int i = 0; i < 2; ++i) {
    s.cam[i].fu = fu;
    s.cam[i].cu = 19.5;
    s.cam[i].axis_yaw = -M_PI / 2 + turn + (i ? misalignment : 0);
    s.cam[i].u_sign = i ? 1 : -1;
  }
  for (int u = 0; u <= 40; ++u) {
    const double xd = (u - 0.5 - 19.5) / fu;
    double x = xd;
    for (int it = 0; it < 30; ++it) x = xd / (1 - 0.14 * x * x);
    s.cam[0].edges.push_back(s.cam[0].axis_yaw - std::atan(x));
  }
  s.kernels = host::default_kernels(M_PI / 3);
  return s;
}

}  // namespace

TEST_GROUP(DeviceSetup){};

TEST(DeviceSetup, DeviceEdgesEqualTheHostsRelativeToCam0) {
  const host::EstimatorSettings s = rig(0.02);
  const host::DeviceSetup d = host::device_setup_from_settings(s);
  STRCMP_EQUAL("ok", protocol::to_string(protocol::validate(d.config)));
  CHECK_EQUAL(protocol::kLooksRight | protocol::kCam1UpsideDown, d.config.orientation);
  CHECK_EQUAL(protocol::kLensCam0, d.config.lens);
  DOUBLES_EQUAL(0.02, std::ldexp(d.config.misalignment, -28), 1e-8);
  CHECK_EQUAL(4, d.config.kernel_count);
  // What the device builds from it.
  EstimatorConfig dev{};
  const EdgeOffsetQ15* const lens[2] = {d.lens[0].data(), nullptr};
  CHECK_TRUE(app::to_estimator_config(d.config, dev, lens));
  STRCMP_EQUAL("ok", to_string(validate(dev)));
  AngleQ28 e0[41], e1[41];
  column_edge_yaws(dev.cam[0], dev.edge_offsets[0], 40, e0);
  column_edge_yaws(dev.cam[1], dev.edge_offsets[1], 40, e1);
  // The device's rig is the host's turned by the common yaw (cam0 to -pi/2).
  const double turn = -M_PI / 2 - s.cam[0].axis_yaw;
  double worst = 0;
  for (int u = 0; u <= 40; ++u) {
    worst = std::fmax(worst, std::fabs(std::ldexp(e0[u], -28) - (s.cam[0].edges[static_cast<size_t>(u)] + turn)));
    const double pin1 = s.cam[1].axis_yaw + turn + std::atan((u - 0.5 - 19.5) / s.cam[1].fu);
    worst = std::fmax(worst, std::fabs(std::ldexp(e1[u], -28) - pin1));
  }
  CHECK(worst < 2e-5);  // half a Q15 step (1.5e-5 rad) plus the Q16 intrinsics
}

TEST(DeviceSetup, RefusesWhatTheHidConfigurationCannotCarry) {
  host::EstimatorSettings s = rig(0.5);  // misalignment beyond 0.35 rad
  CHECK_THROWS(std::invalid_argument, host::device_setup_from_settings(s));
}

TEST(DeviceSetup, FromARecordingWithDistortionAndACalibratedMisalignment) {
  fixture::TempDir dir;
  const Recording rec = load_recording(fixture::write_recording(dir.path() + "/rec"));
  const host::EstimatorSettings s = host::derive_settings(rec, {40, 30});
  CHECK_FALSE(s.cam[0].edges.empty());  // the fixture's sensor.yaml has a lens
  const host::DeviceSetup d = host::device_setup_from_recording(rec, {40, 30}, 0.0123);
  STRCMP_EQUAL("ok", protocol::to_string(protocol::validate(d.config)));
  CHECK_EQUAL(protocol::kLensCam0 | protocol::kLensCam1, d.config.lens);
  CHECK_EQUAL(41u, d.lens[0].size());
  DOUBLES_EQUAL(0.0123, std::ldexp(d.config.misalignment, -28), 1e-8);
  CHECK_EQUAL(host::to_fixed_config(s).baseline, d.config.baseline);
  CHECK_EQUAL(host::to_fixed_config(s).frame_period_us, d.config.frame_period_us);
  // Without a calibrated value the recording's own misalignment is kept.
  const host::DeviceSetup y = host::device_setup_from_recording(rec, {40, 30}, std::nan(""));
  DOUBLES_EQUAL(s.cam[1].axis_yaw - s.cam[0].axis_yaw, std::ldexp(y.config.misalignment, -28), 1e-8);
  // What calibrate --write writes reads back through the text form unchanged.
  host::DeviceSetup back{};
  host::apply_settings_text(back, host::format_setup(d), "written.cfg");
  host::seal_lens(back);
  CHECK_EQUAL(host::format_setup(d), host::format_setup(back));
  CHECK_EQUAL(d.config.lens_crc, back.config.lens_crc);
}
