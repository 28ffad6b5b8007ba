// The KEY=VALUE form of a device configuration with lens tables: lossless
// round trip, errors that name the key (and the file and line), lens lengths.
#include <CppUTest/TestHarness.h>

#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <string>

#include "lumavel/host/config_text.hpp"

using namespace lumavel;
using host::DeviceSetup;

namespace {

DeviceSetup sample() {
  DeviceSetup s;
  s.config = protocol::default_device_config();
  s.config.options = kOptionGyroOffsetLearning;
  s.config.still_distance = 16777;  // ~1 mm
  s.config.still_min_us = 250000;
  for (int u = 0; u <= 40; ++u) s.lens[1].push_back(static_cast<EdgeOffsetQ15>((u - 20) * (u - 20) * (u - 20) / 25));
  host::seal_lens(s);
  return s;
}

std::string error_of(DeviceSetup& s, const std::string& text) {
  try {
    host::apply_settings_text(s, text, "rig.cfg");
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_GROUP(ConfigText){};

TEST(ConfigText, FormatThenParseIsLossless) {
  const DeviceSetup a = sample();
  const std::string text = host::format_setup(a);
  DeviceSetup b;
  b.config = protocol::default_device_config();
  host::apply_settings_text(b, "# a comment\n\n" + text, "rig.cfg");
  host::seal_lens(b);
  CHECK_EQUAL(text, host::format_setup(b));
  CHECK_TRUE(a.lens[1] == b.lens[1]);
  CHECK_TRUE(b.lens[0].empty());
  CHECK_EQUAL(protocol::kLensCam1, b.config.lens);
  CHECK_EQUAL(a.config.lens_crc, b.config.lens_crc);
  CHECK_EQUAL(kOptionGyroOffsetLearning, b.config.options);
  CHECK_EQUAL(250000u, b.config.still_min_us);
  CHECK(text.find("lens_cam0=none\n") != std::string::npos);
  CHECK(text.find("baseline_correction=0\n") != std::string::npos);
}

TEST(ConfigText, ErrorsNameTheFileLineAndKey) {
  DeviceSetup s = sample();
  STRCMP_EQUAL("rig.cfg:3: tau_us: \"fast\" is not an integer in [0, 4294967295]",
               error_of(s, "width=40\n# ok so far\ntau_us=fast\n").c_str());
  CHECK(error_of(s, "width=40\nlens_cam0=0.1,x,0.2\n").find("rig.cfg:2: lens_cam0 value 2: \"x\" is not a number") == 0);
  CHECK(error_of(s, "lens_cam1=0.5,1.5\n").find("rig.cfg:1: lens_cam1 value 2: 1.5 rad is outside [-1, 1)") == 0);
  CHECK(error_of(s, "\n\nno_such_key=1\n").find("rig.cfg:3: unknown configuration key \"no_such_key\"") == 0);
  CHECK(error_of(s, "width\n").find("rig.cfg:1: \"width\" is not KEY=VALUE") == 0);
  CHECK(error_of(s, "gyro_offset_learning=2\n").find("rig.cfg:1: gyro_offset_learning:") == 0);
}

TEST(ConfigText, LensLengthMustMatchTheWidth) {
  DeviceSetup s = sample();
  host::apply_setting(s, "width=64");
  try {
    host::seal_lens(s);
    FAIL("a 41-value table was accepted for 64 columns");
  } catch (const std::runtime_error& e) {
    STRCMP_EQUAL("lens_cam1: 41 values, but width 64 needs 65 (one per column edge)", e.what());
  }
  host::apply_setting(s, "lens_cam1=none");
  host::seal_lens(s);
  CHECK_EQUAL(0, s.config.lens);
  CHECK_EQUAL(0, s.config.lens_crc);
}

TEST(ConfigText, MissingFileIsNamed) {
  DeviceSetup s = sample();
  try {
    host::apply_settings_file(s, "/nonexistent/rig.cfg");
    FAIL("no error");
  } catch (const std::runtime_error& e) {
    STRCMP_EQUAL("/nonexistent/rig.cfg: cannot open configuration file", e.what());
  }
}
