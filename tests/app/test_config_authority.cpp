// The configuration authority (lumavel/units/config_fields.hpp): a value the
// wire codec accepts is one the core accepts, the defaults agree between the
// device and the host, and defaults_for is the one default geometry.
#include <CppUTest/TestHarness.h>

#include <string>

#include "lumavel/app/estimator_config.hpp"
#include "lumavel/host/settings.hpp"
#include "lumavel/protocol/device_config.hpp"

using namespace lumavel;
using config::Quantity;
using config::range;

namespace {

// The device defaults with one field changed: the wire takes it, and so must the core.
template <typename Mutate>
void wire_and_core_agree(Mutate m, const char* what) {
  protocol::DeviceConfig c = protocol::default_device_config();
  m(c);
  CHECK_TEXT(protocol::validate(c) == protocol::ConfigField::kOk, what);
  EstimatorConfig e{};
  CHECK_TEXT(app::to_estimator_config(c, e), what);
  LONGS_EQUAL_TEXT(static_cast<int>(ConfigError::kOk), static_cast<int>(validate(e)), what);
}

}  // namespace

TEST_GROUP(ConfigAuthority){};

TEST(ConfigAuthority, WireBoundsAreCoreBounds) {
  using C = protocol::DeviceConfig;
  wire_and_core_agree([](C& c) { c.baseline = static_cast<LengthQ24>(range<Quantity::kBaseline>.hi); }, "baseline hi");
  wire_and_core_agree([](C& c) { c.baseline = static_cast<LengthQ24>(-range<Quantity::kBaseline>.lo); }, "baseline -lo");
  wire_and_core_agree([](C& c) { c.tau_us = static_cast<uint32_t>(range<Quantity::kTau>.hi); }, "tau hi");
  wire_and_core_agree([](C& c) { c.tau_us = static_cast<uint32_t>(range<Quantity::kTau>.lo); }, "tau lo");
  wire_and_core_agree([](C& c) { c.frame_period_us = static_cast<uint32_t>(range<Quantity::kFramePeriod>.lo); }, "period lo");
  wire_and_core_agree([](C& c) {
    c.frame_period_us = static_cast<uint32_t>(range<Quantity::kFramePeriod>.hi);
    c.max_gap_us = static_cast<uint32_t>(range<Quantity::kMaxGap>.hi);
  }, "period and max gap hi");
  wire_and_core_agree([](C& c) { c.gyro_gap_us = static_cast<uint32_t>(range<Quantity::kGyroGap>.hi); }, "gyro gap hi");
  wire_and_core_agree([](C& c) { c.gyro_gap_us = static_cast<uint32_t>(range<Quantity::kGyroGap>.lo); }, "gyro gap lo");
  wire_and_core_agree([](C& c) { c.normaliser_sigma = static_cast<AngleQ28>(range<Quantity::kKernelSigma>.hi); }, "sigma hi");
  wire_and_core_agree([](C& c) {
    c.misalignment = static_cast<AngleQ28>(range<Quantity::kMisalignment>.hi);
    c.kernels[1] = c.kernels[0];  // the wide kernel would leave the turned view (a geometric check, not a range)
  }, "misalignment");
  wire_and_core_agree([](C& c) {
    c.fu[0] = c.fu[1] = 8 * 65536 * c.width;  // a 7 degree view: kernels at their narrowest fit it
    for (int k = 0; k < c.kernel_count; ++k) c.kernels[k].sigma = static_cast<AngleQ28>(range<Quantity::kKernelSigma>.lo);
  }, "fu 8 x width");
  wire_and_core_agree([](C& c) { c.fu[0] = c.fu[1] = static_cast<PixelQ16>(range<Quantity::kFocalLength>.lo); }, "fu lo");
  wire_and_core_agree([](C& c) { c.still_min_us = static_cast<uint32_t>(range<Quantity::kStillDuration>.hi); }, "still hi");
  wire_and_core_agree([](C& c) { c.still_distance = static_cast<LengthQ24>(range<Quantity::kStillDistance>.lo); }, "still lo");
}

TEST(ConfigAuthority, JustOutsideIsRefusedByBoth) {
  protocol::DeviceConfig c = protocol::default_device_config();
  c.tau_us = static_cast<uint32_t>(range<Quantity::kTau>.hi + 1);
  CHECK(protocol::validate(c) == protocol::ConfigField::kTau);
  c = protocol::default_device_config();
  c.max_gap_us = static_cast<uint32_t>(range<Quantity::kMaxGap>.hi + 1);
  CHECK(protocol::validate(c) == protocol::ConfigField::kMaxGap);
  c = protocol::default_device_config();
  EstimatorConfig e{};
  CHECK(app::to_estimator_config(c, e));
  e.tau_us = static_cast<uint32_t>(range<Quantity::kTau>.hi + 1);
  CHECK(validate(e) == ConfigError::kTau);
  CHECK(app::to_estimator_config(c, e));
  e.baseline = static_cast<LengthQ24>(range<Quantity::kBaseline>.hi + 1);
  CHECK(validate(e) == ConfigError::kBaseline);
}

TEST(ConfigAuthority, DefaultGeometryForAResolution) {
  const protocol::DeviceConfig d = protocol::default_device_config();
  LONGS_EQUAL(2270234, d.fu[0]);  // 34.64 px: 60 degrees over 40 columns
  LONGS_EQUAL(1277952, d.cu[1]);  // 19.5 px
  const protocol::DeviceConfig b = protocol::defaults_for(128, 1);
  LONGS_EQUAL(7264748, b.fu[1]);  // 110.85 px = 64 / tan(30 deg), as the blue pill always had it
  LONGS_EQUAL(4161536, b.cu[0]);  // 63.5 px
  for (int w : {kMinColumns, kDefaultColumns, kMaxColumns}) {
    const protocol::DeviceConfig c = protocol::defaults_for(static_cast<uint16_t>(w), 1);
    CHECK(protocol::validate(c) == protocol::ConfigField::kOk);
  }
  const protocol::DeviceConfig n = protocol::defaults_for(40, 30, config::field_of_view(50 * config::kDeg));
  LONGS_EQUAL(2810848, n.fu[0]);  // 20 / tan(25 deg) = 42.89 px
  LONGS_EQUAL(29281766, n.kernels[0].sigma);  // 25 deg / 4 = 0.10908 rad
  LONGS_EQUAL(2, n.kernels[3].order);
}

TEST(ConfigAuthority, HostDefaultsAreTheDevices) {
  host::EstimatorSettings s;
  s.kernels = host::default_kernels(config::kDefaultFovRad);
  for (int i = 0; i < 2; ++i) {
    s.cam[i].fu = 34.641016;
    s.cam[i].cu = 19.5;
    s.cam[i].axis_yaw = 1.5707963267948966;
  }
  const EstimatorConfig e = host::to_fixed_config(s);
  const protocol::DeviceConfig d = protocol::default_device_config();
  LONGS_EQUAL(d.width, e.width);
  LONGS_EQUAL(d.height, e.height);
  LONGS_EQUAL(d.baseline, e.baseline);
  LONGS_EQUAL(d.normaliser_sigma, e.normaliser.sigma);
  LONGS_EQUAL(d.tau_us, e.tau_us);
  LONGS_EQUAL(d.frame_period_us, e.frame_period_us);
  LONGS_EQUAL(d.max_gap_us, e.max_gap_us);
  LONGS_EQUAL(d.gyro_gap_us, e.gyro_gap_us);
  LONGS_EQUAL(d.low_texture, e.low_texture);
  LONGS_EQUAL(d.saturated_permille, e.saturated_permille);
  LONGS_EQUAL(d.options, e.options);
  LONGS_EQUAL(d.still_distance, e.still_distance);
  LONGS_EQUAL(d.still_min_us, e.still_min_us);
  // One default kernel bank (config_fields.hpp), sized to the same view on both sides.
  LONGS_EQUAL(config::kDefaultKernelCount, e.kernel_count);
  LONGS_EQUAL(d.kernel_count, e.kernel_count);
  for (int k = 0; k < d.kernel_count; ++k) {
    LONGS_EQUAL(d.kernels[k].order, e.kernels[k].order);
    LONGS_EQUAL(d.kernels[k].sigma, e.kernels[k].sigma);
  }
}

// The rules in words (rule_of) are written by hand next to the table: the
// integer bounds they name must be the table's.
TEST(ConfigAuthority, WireRulesNameTheTablesBounds) {
  using F = protocol::ConfigField;
  auto names = [](F f, int64_t v) {
    return std::string(protocol::rule_of(f)).find(std::to_string(v)) != std::string::npos;
  };
  CHECK(names(F::kTau, range<Quantity::kTau>.lo) && names(F::kTau, range<Quantity::kTau>.hi));
  CHECK(names(F::kFramePeriod, range<Quantity::kFramePeriod>.lo) && names(F::kFramePeriod, range<Quantity::kFramePeriod>.hi));
  CHECK(names(F::kMaxGap, range<Quantity::kMaxGap>.hi));
  CHECK(names(F::kGyroGap, range<Quantity::kGyroGap>.lo) && names(F::kGyroGap, range<Quantity::kGyroGap>.hi));
  CHECK(names(F::kStillDuration, range<Quantity::kStillDuration>.lo) &&
        names(F::kStillDuration, range<Quantity::kStillDuration>.hi));
  CHECK(names(F::kSaturatedPermille, range<Quantity::kSaturatedPermille>.hi));
}
