#include <CppUTest/TestHarness.h>

#include <cstring>

#include "lumavel/app/estimator_config.hpp"
#include "lumavel/protocol/crc.hpp"
#include "lumavel/protocol/device_config.hpp"

using namespace lumavel::protocol;
using lumavel::EstimatorConfig;
using lumavel::app::to_estimator_config;

namespace {

DeviceConfig sample() {
  DeviceConfig c = default_device_config();
  c.width = 64;
  c.height = 1;
  c.baseline = -2000000;  // cam1 behind cam0
  c.misalignment = -4000000;
  c.fu[1] = c.fu[0] + 12345;
  c.cu[1] = c.cu[0] - 777;
  c.orientation = kLooksRight | kCam1UpsideDown;
  c.kernel_count = 3;
  c.kernels[2] = KernelSetting{3, 30000000};
  c.kernels[3] = KernelSetting{};  // slots past the count are zero
  c.tau_us = 250000;
  c.saturated_permille = 1000;
  c.options = lumavel::kOptionGyroOffsetLearning;
  c.still_distance = 1677722;
  c.still_min_us = 100000;
  return c;
}

struct Case {
  const char* name;
  void (*mutate)(DeviceConfig&);
  ConfigField expected;
};

const Case kCases[] = {
    {"width low", [](DeviceConfig& c) { c.width = lumavel::kMinColumns - 1; }, ConfigField::kWidth},
    {"width high", [](DeviceConfig& c) { c.width = lumavel::kMaxColumns + 1; }, ConfigField::kWidth},
    {"height 0", [](DeviceConfig& c) { c.height = 0; }, ConfigField::kHeight},
    {"height high", [](DeviceConfig& c) { c.height = lumavel::kMaxRows + 1; }, ConfigField::kHeight},
    {"baseline 0", [](DeviceConfig& c) { c.baseline = 0; }, ConfigField::kBaseline},
    {"baseline tiny", [](DeviceConfig& c) { c.baseline = -16776; }, ConfigField::kBaseline},
    {"baseline huge", [](DeviceConfig& c) { c.baseline = 16777217; }, ConfigField::kBaseline},
    {"misalignment", [](DeviceConfig& c) { c.misalignment = -93952411; }, ConfigField::kMisalignment},
    {"fu 0", [](DeviceConfig& c) { c.fu[1] = 0; }, ConfigField::kFocalLength},
    {"fu huge", [](DeviceConfig& c) { c.fu[0] = 8 * 65536 * 64 + 1; }, ConfigField::kFocalLength},
    {"cu negative", [](DeviceConfig& c) { c.cu[0] = -1; }, ConfigField::kPrincipalPoint},
    {"cu past width", [](DeviceConfig& c) { c.cu[1] = 63 * 65536 + 1; }, ConfigField::kPrincipalPoint},
    {"orientation", [](DeviceConfig& c) { c.orientation = 0x08; }, ConfigField::kOrientation},
    {"normaliser", [](DeviceConfig& c) { c.normaliser_sigma = 0; }, ConfigField::kNormaliserSigma},
    {"kernel count 0", [](DeviceConfig& c) { c.kernel_count = 0; }, ConfigField::kKernelCount},
    {"kernel count 7", [](DeviceConfig& c) { c.kernel_count = 7; }, ConfigField::kKernelCount},
    {"kernel order", [](DeviceConfig& c) { c.kernels[1].order = 4; }, ConfigField::kKernelOrder},
    {"kernel sigma", [](DeviceConfig& c) { c.kernels[0].sigma = 536870913; }, ConfigField::kKernelSigma},
    {"unused slot order", [](DeviceConfig& c) { c.kernels[5].order = 1; }, ConfigField::kKernelOrder},
    {"unused slot sigma", [](DeviceConfig& c) { c.kernels[3].sigma = 5; }, ConfigField::kKernelSigma},
    {"tau", [](DeviceConfig& c) { c.tau_us = 999; }, ConfigField::kTau},
    {"frame period", [](DeviceConfig& c) { c.frame_period_us = 1000001; }, ConfigField::kFramePeriod},
    {"max gap < period", [](DeviceConfig& c) { c.max_gap_us = c.frame_period_us - 1; }, ConfigField::kMaxGap},
    {"gyro gap", [](DeviceConfig& c) { c.gyro_gap_us = 99; }, ConfigField::kGyroGap},
    {"low texture", [](DeviceConfig& c) { c.low_texture = -1; }, ConfigField::kLowTexture},
    {"saturated", [](DeviceConfig& c) { c.saturated_permille = 1001; }, ConfigField::kSaturatedPermille},
    {"options", [](DeviceConfig& c) { c.options = 0x20; /* the first bit no option uses */ }, ConfigField::kOptions},
    {"still distance low", [](DeviceConfig& c) { c.still_distance = 1677; }, ConfigField::kStillDistance},
    {"still distance high", [](DeviceConfig& c) { c.still_distance = 1677723; }, ConfigField::kStillDistance},
    {"still duration low", [](DeviceConfig& c) { c.still_min_us = 99999; }, ConfigField::kStillDuration},
    {"still duration high", [](DeviceConfig& c) { c.still_min_us = 60000001; }, ConfigField::kStillDuration},
    {"lens bits", [](DeviceConfig& c) { c.lens = 0x04; }, ConfigField::kLens},
    {"lens crc without lens", [](DeviceConfig& c) { c.lens_crc = 1; }, ConfigField::kLens},
};

}  // namespace

TEST_GROUP(DeviceConfig){};

TEST(DeviceConfig, DefaultsAndSampleAreValid) {
  CHECK_TRUE(ConfigField::kOk == validate(default_device_config()));
  CHECK_TRUE(ConfigField::kOk == validate(sample()));
}

TEST(DeviceConfig, RoundTripsByteExactly) {
  uint8_t a[kConfigSize], b[kConfigSize];
  CHECK_EQUAL(kConfigSize, encode_config(sample(), a, sizeof a));
  DeviceConfig d{};
  CHECK_TRUE(decode_config(a, sizeof a, d).ok());
  CHECK_EQUAL(kConfigSize, encode_config(d, b, sizeof b));
  MEMCMP_EQUAL(a, b, kConfigSize);
  CHECK_EQUAL(-2000000, d.baseline);
  CHECK_EQUAL(3, d.kernels[2].order);
  CHECK_EQUAL(30000000, d.kernels[2].sigma);
  CHECK_EQUAL(lumavel::kOptionGyroOffsetLearning, d.options);
  CHECK_EQUAL(1677722, d.still_distance);
  CHECK_EQUAL(100000u, d.still_min_us);
  DeviceConfig l = sample();
  l.lens = kLensCam1;
  l.lens_crc = 0xBEEF;
  encode_config(l, a, sizeof a);
  CHECK_TRUE(decode_config(a, sizeof a, d).ok());
  CHECK_EQUAL(kLensCam1, d.lens);
  CHECK_EQUAL(0xBEEF, d.lens_crc);
}

TEST(DeviceConfig, EachOutOfRangeFieldIsNamedByValidateAndDecode) {
  for (const Case& k : kCases) {
    DeviceConfig c = sample();
    k.mutate(c);
    const ConfigField f = validate(c);
    if (f != k.expected) FAIL(k.name);
    uint8_t buf[kConfigSize];
    encode_config(c, buf, sizeof buf);
    DeviceConfig out = sample();
    out.tau_us = 4242;
    const DecodeResult r = decode_config(buf, sizeof buf, out);
    CHECK_TRUE(ReportError::kOutOfRange == r.error);
    STRCMP_EQUAL(to_string(k.expected), r.field);
    CHECK_EQUAL(4242u, out.tau_us);  // untouched on refusal
    EstimatorConfig e{};
    e.tau_us = 17;
    CHECK_FALSE(to_estimator_config(c, e));
    CHECK_EQUAL(17u, e.tau_us);
  }
}

TEST(DeviceConfig, MalformedReportsRejected) {
  uint8_t good[kConfigSize];
  encode_config(sample(), good, sizeof good);
  DeviceConfig d{};
  for (size_t n = 0; n < kConfigSize; ++n) {
    CHECK_TRUE(ReportError::kShort == decode_config(good, n, d).error);
  }
  uint8_t buf[kConfigSize];
  std::memcpy(buf, good, sizeof buf);
  buf[0] = kReportDeviceInfo;
  CHECK_TRUE(ReportError::kWrongId == decode_config(buf, sizeof buf, d).error);
  std::memcpy(buf, good, sizeof buf);
  buf[1] = kConfigVersion + 1;
  CHECK_TRUE(ReportError::kBadVersion == decode_config(buf, sizeof buf, d).error);
  for (size_t bit = 16; bit < 8 * kConfigSize; ++bit) {
    std::memcpy(buf, good, sizeof buf);
    buf[bit / 8] = static_cast<uint8_t>(buf[bit / 8] ^ (1u << (bit % 8)));
    CHECK_TRUE(ReportError::kBadCrc == decode_config(buf, sizeof buf, d).error);
  }
}

TEST(DeviceConfig, MapsToEstimatorConfig) {
  const DeviceConfig c = sample();
  EstimatorConfig e{};
  CHECK_TRUE(to_estimator_config(c, e));
  CHECK_EQUAL(64, e.width);
  CHECK_EQUAL(1, e.height);
  CHECK_EQUAL(c.baseline, e.baseline);
  // Looking right: cam0's axis at -pi/2, cam1's rotated by the misalignment.
  CHECK_EQUAL(-421657428, e.cam[0].axis_yaw);
  CHECK_EQUAL(-421657428 + c.misalignment, e.cam[1].axis_yaw);
  CHECK_EQUAL(-1, e.cam[0].u_sign);  // upright
  CHECK_EQUAL(1, e.cam[1].u_sign);   // upside down
  CHECK_EQUAL(c.fu[1], e.cam[1].fu);
  CHECK_EQUAL(c.cu[1], e.cam[1].cu);
  CHECK_EQUAL(0, e.normaliser.order);
  CHECK_EQUAL(c.normaliser_sigma, e.normaliser.sigma);
  CHECK_EQUAL(3, e.kernel_count);
  CHECK_EQUAL(3, e.kernels[2].order);
  CHECK_EQUAL(c.kernels[2].sigma, e.kernels[2].sigma);
  CHECK_EQUAL(c.tau_us, e.tau_us);
  CHECK_EQUAL(c.frame_period_us, e.frame_period_us);
  CHECK_EQUAL(c.max_gap_us, e.max_gap_us);
  CHECK_EQUAL(c.gyro_gap_us, e.gyro_gap_us);
  CHECK_EQUAL(c.low_texture, e.low_texture);
  CHECK_EQUAL(c.saturated_permille, e.saturated_permille);
  CHECK_EQUAL(c.options, e.options);
  CHECK_EQUAL(c.still_distance, e.still_distance);
  CHECK_EQUAL(c.still_min_us, e.still_min_us);
  POINTERS_EQUAL(nullptr, e.edge_offsets[0]);
  POINTERS_EQUAL(nullptr, e.edge_offsets[1]);
}

TEST(DeviceConfig, LensTablesReachTheEstimatorOnlyWhenNamed) {
  DeviceConfig c = sample();
  const lumavel::EdgeOffsetQ15 t0[1] = {0}, t1[1] = {0};
  const lumavel::EdgeOffsetQ15* const both[2] = {t0, t1};
  EstimatorConfig e{};
  c.lens = kLensCam1;
  CHECK_FALSE(to_estimator_config(c, e));  // named but not given
  const lumavel::EdgeOffsetQ15* const only0[2] = {t0, nullptr};
  CHECK_FALSE(to_estimator_config(c, e, only0));
  CHECK_TRUE(to_estimator_config(c, e, both));
  POINTERS_EQUAL(nullptr, e.edge_offsets[0]);
  POINTERS_EQUAL(t1, e.edge_offsets[1]);
}

TEST(DeviceConfig, DefaultsCarryTheEstimatorsOwnDefaults) {
  const DeviceConfig c = default_device_config();
  CHECK_EQUAL(lumavel::kOptionBaselineCorrection | lumavel::kOptionGyroOffsetLearning | lumavel::kOptionPhotometricMatch, c.options);
  CHECK_EQUAL(33554, c.still_distance);  // 2 mm
  CHECK_EQUAL(500000u, c.still_min_us);
  CHECK_EQUAL(0, c.lens);
}

// The elevation band is the default for wide views only (one rule for the
// device and the host: config::elevation_band_for).
TEST(DeviceConfig, TheElevationBandIsTheDefaultFromEightyDegrees) {
  const double deg = lumavel::config::kDeg;
  CHECK_EQUAL(0, default_device_config().options & lumavel::kOptionElevationBand);  // 60 degrees
  CHECK_EQUAL(0, defaults_for(40, 30, lumavel::config::field_of_view(79.9 * deg)).options & lumavel::kOptionElevationBand);
  CHECK_EQUAL(lumavel::kOptionElevationBand,
              defaults_for(40, 30, lumavel::config::field_of_view(80 * deg)).options & lumavel::kOptionElevationBand);
  CHECK_EQUAL(lumavel::kOptionElevationBand,
              defaults_for(40, 30, lumavel::config::field_of_view(120 * deg)).options & lumavel::kOptionElevationBand);
  CHECK_TRUE(validate(defaults_for(40, 30, lumavel::config::field_of_view(120 * deg))) == ConfigField::kOk);
}

TEST(DeviceConfig, LooksLeftByDefault) {
  EstimatorConfig e{};
  CHECK_TRUE(to_estimator_config(default_device_config(), e));
  CHECK_EQUAL(421657428, e.cam[0].axis_yaw);
  CHECK_EQUAL(421657428, e.cam[1].axis_yaw);
  CHECK_EQUAL(-1, e.cam[1].u_sign);
}

TEST(DeviceConfig, FieldsHaveNames) {
  STRCMP_EQUAL("baseline", to_string(ConfigField::kBaseline));
  CHECK_EQUAL(static_cast<int>(kMaxConfigStatus), static_cast<int>(ConfigField::kStore));
}
