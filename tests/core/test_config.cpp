#include <CppUTest/TestHarness.h>

#include <cstring>
#include <stdexcept>
#include <string>

#include "lumavel/core/config.hpp"
#include "lumavel/core/estimator.hpp"
#include "lumavel/core/kernel_bank.hpp"

#include <utility>
#include "lumavel/host/settings.hpp"
#include "synthetic_rig.hpp"

using namespace lumavel;

namespace {
EstimatorConfig good() { return host::to_fixed_config(test::SyntheticRig{}.settings()); }
}  // namespace

TEST_GROUP(Config){};

TEST(Config, DefaultRigIsValid) { CHECK(validate(good()) == ConfigError::kOk); }

TEST(Config, EachFieldOutOfRangeIsNamed) {
  struct Case {
    void (*mutate)(EstimatorConfig&);
    ConfigError want;
  };
  const Case cases[] = {
      {[](EstimatorConfig& c) { c.width = 1; }, ConfigError::kWidth},  // single column
      {[](EstimatorConfig& c) { c.width = kMaxColumns + 1; }, ConfigError::kWidth},
      {[](EstimatorConfig& c) { c.height = 0; }, ConfigError::kHeight},
      {[](EstimatorConfig& c) { c.height = kMaxRows + 1; }, ConfigError::kHeight},
      {[](EstimatorConfig& c) { c.cam[1].fu = 0; }, ConfigError::kFocalLength},
      {[](EstimatorConfig& c) { c.cam[0].cu = -(100 << 16); }, ConfigError::kPrincipalPoint},
      {[](EstimatorConfig& c) { c.cam[0].axis_yaw = fx::kPiQ28 + 1; }, ConfigError::kAxisYaw},
      {[](EstimatorConfig& c) { c.cam[0].u_sign = 0; }, ConfigError::kUSign},
      {[](EstimatorConfig& c) { c.baseline = 0; }, ConfigError::kBaseline},
      {[](EstimatorConfig& c) { c.kernel_count = 0; }, ConfigError::kKernelCount},
      {[](EstimatorConfig& c) { c.kernels[0].order = 4; }, ConfigError::kKernelOrder},
      {[](EstimatorConfig& c) { c.normaliser.order = 1; }, ConfigError::kKernelOrder},
      {[](EstimatorConfig& c) { c.kernels[0].sigma = 1000; }, ConfigError::kKernelSigma},
      {[](EstimatorConfig& c) { c.kernels[0].sigma = 20 * 4685082; }, ConfigError::kKernelOutsideView},
      {[](EstimatorConfig& c) { c.tau_us = 0; }, ConfigError::kTau},
      {[](EstimatorConfig& c) { c.frame_period_us = 0; }, ConfigError::kFramePeriod},
      {[](EstimatorConfig& c) { c.max_gap_us = 1; }, ConfigError::kMaxGap},
      {[](EstimatorConfig& c) { c.gyro_gap_us = 0; }, ConfigError::kGyroGap},
      {[](EstimatorConfig& c) { c.low_texture = -1; }, ConfigError::kLowTexture},
      {[](EstimatorConfig& c) { c.saturated_permille = 1001; }, ConfigError::kSaturatedPermille},
      {[](EstimatorConfig& c) { c.options = 0x80; }, ConfigError::kOptions},
      {[](EstimatorConfig& c) { c.still_distance = 0; }, ConfigError::kStill},
      {[](EstimatorConfig& c) { c.still_min_us = 0; }, ConfigError::kStill},
  };
  for (const Case& k : cases) {
    EstimatorConfig c = good();
    k.mutate(c);
    LONGS_EQUAL(static_cast<int>(k.want), static_cast<int>(validate(c)));
    CHECK(std::strlen(to_string(k.want)) > 5);
  }
}

TEST(Config, HostQuantisationRefusesWhatDoesNotFit) {
  auto s = test::SyntheticRig{}.settings();
  s.baseline = 300;  // 300 m: outside Q7.24
  try {
    host::to_fixed_config(s);
    FAIL("expected an exception");
  } catch (const std::invalid_argument& e) {
    CHECK(std::string(e.what()).find("baseline") != std::string::npos);
  }
  s = test::SyntheticRig{}.settings();
  s.cam[0].fu = std::nan("");
  CHECK_THROWS(std::invalid_argument, host::to_fixed_config(s));
  s = test::SyntheticRig{}.settings();
  s.width = 1;
  CHECK_THROWS(std::invalid_argument, host::to_fixed_config(s));
}

// A time in a refusal is the one its rule is checked on, whole microseconds:
// a frame period of 1.000000501 s (1000001 us) said 'frame period = 1 s:
// frame period must be 1 ms..1 s', a refusal its own words allow (a gyro gap
// of 1.0000005 s the same).
TEST(Config, ATimeInARefusalIsItsWholeMicroseconds) {
  auto s = test::SyntheticRig{}.settings();
  s.frame_period = 1.000000501;
  s.max_gap = 4;
  try {
    host::to_fixed_config(s);
    FAIL("accepted");
  } catch (const std::invalid_argument& e) {
    STRCMP_EQUAL("frame period = 1.000001 s: frame period must be 1 ms..1 s", e.what());
  }
  s = test::SyntheticRig{}.settings();
  s.gyro_gap = 1.0000005;
  try {
    host::to_fixed_config(s);
    FAIL("accepted");
  } catch (const std::invalid_argument& e) {
    STRCMP_EQUAL("gyro gap = 1.000001 s: gyro gap must be 0.1 ms..1 s", e.what());
  }
  s = test::SyntheticRig{}.settings();
  s.frame_period = 0.0009994;  // 999 us
  try {
    host::to_fixed_config(s);
    FAIL("accepted");
  } catch (const std::invalid_argument& e) {
    STRCMP_EQUAL("frame period = 0.000999 s: frame period must be 1 ms..1 s", e.what());
  }
  // Under half a microsecond (frame timestamps in milliseconds read as
  // nanoseconds, 17 ns apart) was said as 'frame period = 0 s'.
  s = test::SyntheticRig{}.settings();
  s.frame_period = 17e-9;
  try {
    host::to_fixed_config(s);
    FAIL("accepted");
  } catch (const std::invalid_argument& e) {
    STRCMP_EQUAL("frame period = 1.7e-08 s: frame period must be 1 ms..1 s", e.what());
  }
}

TEST(Config, EstimatorKeepsItsConfigurationOnError) {
  Estimator* est = new Estimator;
  CHECK(est->configure(good()) == ConfigError::kOk);
  EstimatorConfig bad = good();
  bad.width = 3;
  CHECK(est->configure(bad) == ConfigError::kWidth);
  LONGS_EQUAL(40, est->config().width);
  delete est;
}

TEST(Config, LensTableMustKeepTheEdgesMonotonic) {
  EstimatorConfig c = good();
  EdgeOffsetQ15 lens[kMaxColumns + 1] = {};
  c.edge_offsets[0] = lens;
  CHECK(validate(c) == ConfigError::kOk);
  // Edge 4 pushed past edge 3 (columns are ~0.026 rad wide at 40 x 60 deg).
  lens[4] = static_cast<EdgeOffsetQ15>(c.cam[0].u_sign * 0.05 * 32768);
  LONGS_EQUAL(static_cast<int>(ConfigError::kColumnEdges), static_cast<int>(validate(c)));
}

TEST(Config, LensTableIsAddedToThePinholeEdges) {
  EstimatorConfig c = good();
  EdgeOffsetQ15 lens[kMaxColumns + 1] = {};
  for (int u = 0; u <= c.width; ++u) lens[u] = static_cast<EdgeOffsetQ15>((u - c.width / 2) * 7);
  AngleQ28 pin[kMaxColumns + 1], with[kMaxColumns + 1];
  pinhole_column_edges(c.cam[0], c.width, pin);
  column_edge_yaws(c.cam[0], lens, c.width, with);
  for (int u = 0; u <= c.width; ++u) LONGS_EQUAL(pin[u] + lens[u] * 8192, with[u]);
  column_edge_yaws(c.cam[0], nullptr, c.width, with);
  for (int u = 0; u <= c.width; ++u) LONGS_EQUAL(pin[u], with[u]);
}
