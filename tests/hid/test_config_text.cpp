// The KEY=VALUE form of a device configuration with lens tables: lossless
// round trip, errors that name the key (and the file and line), lens lengths.
#include <CppUTest/TestHarness.h>

#include <sys/stat.h>
#include <unistd.h>
#include <cstdlib>

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
  STRCMP_EQUAL("rig.cfg:3: tau_us = fast: not a whole number; tau_us must be 1000..10000000 us",
               error_of(s, "width=40\n# ok so far\ntau_us=fast\n").c_str());
  CHECK(error_of(s, "width=40\nlens_cam0=0.1,x,0.2\n").find("rig.cfg:2: lens_cam0 value 2: \"x\" is not a number") == 0);
  CHECK(error_of(s, "lens_cam1=0.5,1.5\n").find("rig.cfg:1: lens_cam1 value 2: 1.5 rad is outside [-1, 1)") == 0);
  CHECK(error_of(s, "\n\nno_such_key=1\n").find("rig.cfg:3: unknown configuration key \"no_such_key\"") == 0);
  CHECK(error_of(s, "width\n").find("rig.cfg:1: \"width\" is not KEY=VALUE") == 0);
  STRCMP_EQUAL("rig.cfg:1: gyro_offset_learning = 2: gyro_offset_learning must be 0 or 1",
               error_of(s, "gyro_offset_learning=2\n").c_str());
}

// A lens value is kept in 1/32768 rad steps, -1 to 32767/32768 rad: one just
// below 1 rad rounds to 1, beyond the table, and was refused as '0.999985 rad
// is outside [-1, 1)', a refusal its own words allow.
TEST(ConfigText, ALensValueThatRoundsTo1RadSaysSo) {
  DeviceSetup s = sample();
  STRCMP_EQUAL("rig.cfg:1: lens_cam0 value 2: 0.999985 rad rounds to 1 rad in the table's steps of 1/32768 rad, "
               "outside [-1, 1): at most 0.99997 rad (32767/32768)",
               error_of(s, "lens_cam0=0.5,0.999985\n").c_str());
  STRCMP_EQUAL("rig.cfg:1: lens_cam0 value 1: -1.00002 rad is outside [-1, 1)",
               error_of(s, "lens_cam0=-1.00002\n").c_str());
  STRCMP_EQUAL("", error_of(s, "lens_cam0=-1,0.99997,0.999984\n").c_str());
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
    STRCMP_EQUAL("/nonexistent/rig.cfg: does not exist", e.what());
  }
}

namespace {

// The refusal of check_settings_offline for `text` written to the file
// /tmp/lumavel_config_text_PID`suffix`, or "".
std::string offline_refusal_of_file(const std::string& suffix, const std::string& text) {
  const std::string path = "/tmp/lumavel_config_text_" + std::to_string(::getpid()) + suffix;
  { std::ofstream(path, std::ios::binary) << text; }
  std::string why;
  try {
    host::GivenSettings g;
    g.add_file(path);
    host::check_settings_offline(g);
  } catch (const std::runtime_error& e) {
    why = e.what();
  }
  std::remove(path.c_str());
  return why;
}

// The refusal of check_settings_offline for `text` read as rig.cfg, or "".
std::string offline_refusal(const std::string& text) {
  std::string why = offline_refusal_of_file(".cfg", text);
  const size_t at = why.find(".cfg:");
  if (at == std::string::npos) return why;
  const std::string path = why.substr(0, at + 4);  // the file, named again by a partner key's line
  for (size_t p = 0; (p = why.find(path, p)) != std::string::npos; p += 7) why.replace(p, path.size(), "rig.cfg");
  return why;
}

}  // namespace

TEST(ConfigText, OfflineCheckNamesTheLineTheKeyTheValueAndTheRule) {
  STRCMP_EQUAL("rig.cfg:2: width = 0: width must be 16..160 columns", offline_refusal("height=30\nwidth=0\n").c_str());
  STRCMP_EQUAL("rig.cfg:1: baseline_m = 5: baseline |h| must be 0.001..1 m", offline_refusal("baseline_m=5\n").c_str());
  STRCMP_EQUAL("rig.cfg:3: misalignment_rad = 0.5: misalignment must be -0.35..0.35 rad",
               offline_refusal("# rig\n\nmisalignment_rad=0.5\n").c_str());
  STRCMP_EQUAL("rig.cfg:1: kernels = 9:0.07: kernel orders must be 0..3", offline_refusal("kernels=9:0.07\n").c_str());
  // A rule of two keys says the other one's value and line (was: 'width = 20:
  // cu must be 0..width - 1 px', cu0_px = 19.5 on line 1 unsaid).
  STRCMP_EQUAL("rig.cfg:2: max_gap_us = 20000: max_gap_us must be frame_period_us..4000000 us (with "
               "frame_period_us = 50000 at rig.cfg:1)",
               offline_refusal("frame_period_us=50000\nmax_gap_us=20000\n").c_str());
  STRCMP_EQUAL("rig.cfg:2: cu0_px = 63.5: cu must be 0..width - 1 px (with width = 40 at rig.cfg:1)",
               offline_refusal("width=40\ncu0_px=63.5\n").c_str());
  STRCMP_EQUAL("rig.cfg:2: width = 20: cu must be 0..width - 1 px (with cu0_px = 19.5 at rig.cfg:1)",
               offline_refusal("cu0_px=19.5\nwidth=20\n").c_str());
  STRCMP_EQUAL("rig.cfg:2: lens_cam0 = 0.1,0.2: 2 values, but width 40 needs 41 (one per column edge)",
               offline_refusal("width=40\nlens_cam0=0.1,0.2\n").c_str());
  STRCMP_EQUAL("rig.cfg:1: tau_us = fast: not a whole number; tau_us must be 1000..10000000 us",
               offline_refusal("tau_us=fast\n").c_str());
}

// A value beyond what its field holds is told by the key's rule, the same as
// one just outside it (not "[0, 65535]" or "out of range"); one that is no
// number says so and the rule.
TEST(ConfigText, ValuesBeyondTheirFieldGetTheRule) {
  STRCMP_EQUAL("rig.cfg:1: width = -3: width must be 16..160 columns", offline_refusal("width=-3\n").c_str());
  STRCMP_EQUAL("rig.cfg:1: width = 99999999999999999999: width must be 16..160 columns",
               offline_refusal("width=99999999999999999999\n").c_str());
  STRCMP_EQUAL("rig.cfg:3: fu0_px = 1e300: fu must be 1..8 * width px",
               offline_refusal("width=40\nheight=30\nfu0_px=1e300\n").c_str());
  STRCMP_EQUAL("rig.cfg:1: baseline_m = 1e400: baseline |h| must be 0.001..1 m",
               offline_refusal("baseline_m=1e400\n").c_str());
  // One too small for a double is not beyond its field (was: 'lens_cam0 value
  // 2: 1e-400 rad is outside [-1, 1)', a rule the value meets).
  STRCMP_EQUAL("rig.cfg:1: misalignment_rad = 1e-400: nearer 0 than the smallest number (about 2.2e-308); "
               "misalignment must be -0.35..0.35 rad",
               offline_refusal("misalignment_rad=1e-400\n").c_str());
  STRCMP_EQUAL("rig.cfg:1: lens_cam0 value 2: \"1e-400\" is nearer 0 than the smallest number (about 2.2e-308)",
               offline_refusal("lens_cam0=0,1e-400\n").c_str());
  STRCMP_EQUAL("rig.cfg:1: baseline_m = nan: not a finite number; baseline |h| must be 0.001..1 m",
               offline_refusal("baseline_m=nan\n").c_str());
  STRCMP_EQUAL("rig.cfg:1: gyro_offset_learning = yes: not a whole number; gyro_offset_learning must be 0 or 1",
               offline_refusal("gyro_offset_learning=yes\n").c_str());
  STRCMP_EQUAL("rig.cfg:1: kernels = 1x:0.07: not a whole number; kernels are ORDER:SIGMA_RAD[,...], 1..6 of them, "
               "orders 0..3, sigmas 0.00873..0.785 rad (0.5..45 deg)",
               offline_refusal("kernels=1x:0.07\n").c_str());
}

// The bounds a rule names are accepted: the sigmas' lower one, 0.5 deg, was
// written 0.0087 rad, which is 0.4985 deg: 'normaliser_sigma_rad = 0.0087:
// normaliser sigma must be 0.0087..0.785 rad', a refusal its own rule allows.
TEST(ConfigText, TheBoundsARuleNamesAreAccepted) {
  STRCMP_EQUAL("rig.cfg:1: normaliser_sigma_rad = 0.0087: normaliser sigma must be 0.00873..0.785 rad (0.5..45 deg)",
               offline_refusal("normaliser_sigma_rad=0.0087\n").c_str());
  STRCMP_EQUAL("rig.cfg:1: kernels = 1:0.0087: kernel sigmas must be 0.00873..0.785 rad (0.5..45 deg)",
               offline_refusal("kernels=1:0.0087\n").c_str());
  STRCMP_EQUAL("", offline_refusal("normaliser_sigma_rad=0.00873\n").c_str());
  STRCMP_EQUAL("", offline_refusal("normaliser_sigma_rad=0.785\n").c_str());
  STRCMP_EQUAL("", offline_refusal("kernels=1:0.00873,0:0.785\n").c_str());
}

// A whole number is written as the command lines take theirs: "040" is 32
// to C's base-0 readers (and to CLI11's), 40 here: refused, not guessed
// (was: width=040 set 40 while --width 040 ran at 32). A sign is a number's.
TEST(ConfigText, AWholeNumberWithALeadingZeroIsRefused) {
  STRCMP_EQUAL("rig.cfg:1: width = 040: a leading zero (octal to some readers, decimal to others): write the number "
               "without it; width must be 16..160 columns",
               offline_refusal("width=040\n").c_str());
  STRCMP_EQUAL("rig.cfg:2: kernels = 1:0.07,01:0.14: a leading zero (octal to some readers, decimal to others): write "
               "the number without it; kernels are ORDER:SIGMA_RAD[,...], 1..6 of them, orders 0..3, sigmas "
               "0.00873..0.785 rad (0.5..45 deg)",
               offline_refusal("width=40\nkernels=1:0.07,01:0.14\n").c_str());
  STRCMP_EQUAL("rig.cfg:1: tau_us = 0x10: not a whole number; tau_us must be 1000..10000000 us",
               offline_refusal("tau_us=0x10\n").c_str());
  DeviceSetup s = sample();
  STRCMP_EQUAL("", error_of(s, "width=+64\nkernels=1:0.07, 0:0.14\nbaseline_correction=0\n").c_str());
  LONGS_EQUAL(64, s.config.width);
  LONGS_EQUAL(0, s.config.kernels[1].order);
}

// Two values for one key in a file, or a file that sets nothing, are refused:
// which was meant is not for lumavel to guess.
TEST(ConfigText, OneLensValueIsOneValue) {
  STRCMP_EQUAL("rig.cfg:2: lens_cam0 = 0.1: 1 value, but width 40 needs 41 (one per column edge)",
               offline_refusal("width=40\nlens_cam0=0.1\n").c_str());
}

TEST(ConfigText, AKeyTwiceInAFileOrNoSettingIsRefused) {
  const std::string twice = offline_refusal("width=40\nheight=30\nwidth=20\n");
  STRCMP_CONTAINS("rig.cfg:3: width is given again (first at ", twice.c_str());
  STRCMP_CONTAINS(".cfg:1): one value per key in a file", twice.c_str());
  CHECK(offline_refusal("# only a comment\n\n").find(".cfg: no KEY=VALUE line (only blank lines and # comments)") !=
        std::string::npos);
}

// What depends on a key not given is not refused: the device may have it.
TEST(ConfigText, OfflineCheckRefusesNothingValid) {
  STRCMP_EQUAL("", offline_refusal("cu0_px=63.5\nfu0_px=110.85\n").c_str());
  STRCMP_EQUAL("", offline_refusal("max_gap_us=20000\n").c_str());
  STRCMP_EQUAL("", offline_refusal("lens_cam0=0.1,0.2\n").c_str());
  const DeviceSetup s = sample();
  STRCMP_EQUAL("", offline_refusal(host::format_setup(s)).c_str());  // what config get prints
}

// A UTF-8 byte-order mark, CRLF line ends and spaces around = are read as
// editors write them.
// A file saved as UTF-16 (Notepad's "Unicode", Windows PowerShell's '>') is
// said as such: it was '"\xFF\xFEw" is followed by a NUL byte (character 4):
// not a KEY=VALUE setting'.
TEST(ConfigText, AFileInUtf16IsSaidAsSuch) {
  DeviceSetup s = sample();
  STRCMP_EQUAL("rig.cfg:1: the file is UTF-16 text (little-endian: it starts with the byte-order mark FF FE): the "
               "tools read ASCII or UTF-8 text (save it as UTF-8)",
               error_of(s, std::string("\xFF\xFEw\0=\0" "4\0" "0\0\n\0", 12)).c_str());
}

TEST(ConfigText, ByteOrderMarkCrlfAndSpacesAreAccepted) {
  DeviceSetup s = sample();
  STRCMP_EQUAL("", error_of(s, "\xEF\xBB\xBFwidth = 64\r\n  tau_us=  250000 \r\nlook =right\n").c_str());
  LONGS_EQUAL(64, s.config.width);
  LONGS_EQUAL(250000, s.config.tau_us);
  CHECK(s.config.orientation & protocol::kLooksRight);
  STRCMP_EQUAL("rig.cfg:1: \"= 3\" is not KEY=VALUE (keys: `lumavel-read config --help`)", error_of(s, "= 3\n").c_str());
}

TEST(ConfigText, ADirectoryIsNotAConfigurationFile) {
  DeviceSetup s = sample();
  try {
    host::apply_settings_file(s, "/tmp");
    FAIL("a directory was read as a configuration file");
  } catch (const std::runtime_error& e) {
    STRCMP_EQUAL("/tmp: is a folder, not a configuration file", e.what());
  }
}

// A FIFO is refused before it is opened: reading one would wait for a writer.
TEST(ConfigText, AFifoOrADeviceIsNotAConfigurationFile) {
  DeviceSetup s = sample();
  char dir[] = "/tmp/lumavel_cfg_fifo_XXXXXX";
  CHECK(mkdtemp(dir) != nullptr);
  const std::string fifo = std::string(dir) + "/rig.cfg";
  CHECK(::mkfifo(fifo.c_str(), 0600) == 0);
  std::string fifo_error, device_error;
  try {
    host::apply_settings_file(s, fifo);
  } catch (const std::runtime_error& e) {
    fifo_error = e.what();
  }
  ::unlink(fifo.c_str());
  ::rmdir(dir);
  STRCMP_EQUAL((fifo + ": is a FIFO (named pipe), not a configuration file").c_str(), fifo_error.c_str());
  try {
    host::apply_settings_file(s, "/dev/zero");
  } catch (const std::runtime_error& e) {
    device_error = e.what();
  }
  STRCMP_EQUAL("/dev/zero: is a character device node, not a configuration file", device_error.c_str());
}

// With the device's configuration: the key given is blamed; a device value
// that the given keys break is named by its keys.
TEST(ConfigText, DeviceCheckBlamesTheGivenKey) {
  DeviceSetup device = sample();  // 40 columns
  host::GivenSettings g;
  g.add("cu0_px=63.5", "command line");
  STRCMP_EQUAL("command line: cu0_px = 63.5: cu must be 0..width - 1 px", host::check_settings(device, g).c_str());
  g.add("width=40", "command line");
  STRCMP_EQUAL("command line: cu0_px = 63.5: cu must be 0..width - 1 px (with width = 40 on the command line)",
               host::check_settings(device, g).c_str());
  host::GivenSettings narrow;
  narrow.add("width = 16", "command line");  // the device's lens table has 41 values
  STRCMP_EQUAL("command line: width = 16: 41 values, but width 16 needs 17 (one per column edge)",
               host::check_settings(device, narrow).c_str());
  device.lens[1].clear();  // now the device's cu (19.5 px) no longer fits 16 columns
  STRCMP_EQUAL("command line: width = 16: cu must be 0..width - 1 px", host::check_settings(device, narrow).c_str());
}

// A NUL byte inside a value used to end the number there (strtod):
// "tau_us=25<NUL>0000" was read as 25. Refused, in a file and offline alike.
TEST(ConfigText, ANulByteIsRefusedNotTruncated) {
  DeviceSetup s = sample();
  const uint32_t tau = s.config.tau_us;
  STRCMP_EQUAL("rig.cfg:2: \"tau_us=25\" is followed by a NUL byte (character 10): not a KEY=VALUE setting",
               error_of(s, std::string("width=40\ntau_us=25\0" "0000\n", 24)).c_str());
  LONGS_EQUAL(tau, s.config.tau_us);
  STRCMP_EQUAL("rig.cfg:1: \"baseline_m=0.0\" is followed by a NUL byte (character 15): not a KEY=VALUE setting",
               offline_refusal(std::string("baseline_m=0.0\0" "8\n", 17)).c_str());
  STRCMP_EQUAL("rig.cfg:1: \"look=le\" is followed by a NUL byte (character 8): not a KEY=VALUE setting",
               offline_refusal(std::string("look=le\0" "ft\n", 11)).c_str());
}

// Bytes that show nothing are shown as \xNN too: a byte-order mark before a
// later key read 'unknown configuration key "height"', a binary file's bytes
// and a C1 control (U+009B, a terminal's CSI) went out as they were. Text in
// UTF-8 is shown as it is.
TEST(ConfigText, InvisibleAndInvalidBytesInAMessageAreShownEscaped) {
  DeviceSetup s = sample();
  STRCMP_CONTAINS("rig.cfg:2: unknown configuration key \"\\xEF\\xBB\\xBFheight\"",
                  error_of(s, "\xEF\xBB\xBFwidth=40\n\xEF\xBB\xBFheight=30\n").c_str());
  STRCMP_EQUAL("rig.cfg:1: look: use left or right, not \"\\xFF\\xFEle\\xC2\\x9B2J\\xE2\\x80\\xAEft\"",
               error_of(s, "look=\xFF\xFEle\xC2\x9B" "2J\xE2\x80\xAE" "ft\n").c_str());
  STRCMP_EQUAL("rig.cfg:1: look: use left or right, not \"gauche \xC3\xA0 \xE5\xB7\xA6\"",
               error_of(s, "look=gauche \xC3\xA0 \xE5\xB7\xA6\n").c_str());
}

// A value shown in a refusal is shown as shown_path shows it (control
// characters as \xNN): look's, a kernel list's and a lens value's were sent
// to the terminal as they were, escape sequences and all.
TEST(ConfigText, ControlCharactersInARefusedValueAreShownEscaped) {
  DeviceSetup s = sample();
  STRCMP_EQUAL("rig.cfg:1: look: use left or right, not \"ri\\x1B[2Jght\"",
               error_of(s, "look=ri\x1b[2Jght\n").c_str());
  STRCMP_EQUAL("rig.cfg:1: kernels: \"1:0.07,\\x1B[31m\" is not ORDER:SIGMA_RAD[,...] with at most 6 kernels",
               error_of(s, "kernels=1:0.07,\x1b[31m\n").c_str());
  STRCMP_EQUAL("rig.cfg:1: lens_cam0 value 2: \"\\x1B0.2\" is not a number",
               error_of(s, "lens_cam0=0.1,\x1b" "0.2\n").c_str());
  STRCMP_EQUAL("rig.cfg:1: \"look=\\x07le\" is followed by a NUL byte (character 9): not a KEY=VALUE setting",
               error_of(s, std::string("look=\ale\0" "ft\n", 12)).c_str());
}

// The file's name is shown as its values are: a configuration file named
// 'rig<ESC>[2J.cfg' cleared the terminal with its refusals ('rig[2J.cfg:1:
// width = 0: ...'), as a line with CR-only ends and the offline check did.
TEST(ConfigText, TheFilesNameIsShownLikeAValue) {
  DeviceSetup s = sample();
  STRCMP_EQUAL("rig\\x1B[2J.cfg:1: tau_us = fast: not a whole number; tau_us must be 1000..10000000 us",
               [&] {
                 try {
                   host::apply_settings_text(s, "tau_us=fast\n", "rig\x1b[2J.cfg");
                 } catch (const std::runtime_error& e) {
                   return std::string(e.what());
                 }
                 return std::string();
               }()
                   .c_str());
  const std::string why = offline_refusal_of_file("\x1b[2J.cfg", "height=30\nwidth=0\n");
  STRCMP_EQUAL(("/tmp/lumavel_config_text_" + std::to_string(::getpid()) +
                "\\x1B[2J.cfg:2: width = 0: width must be 16..160 columns")
                   .c_str(),
               why.c_str());
}
