// The corrupted-input corpus (issue 15, "Tests that stay"): every entry is a
// damage done to an intact input, generated here from the fixture, with its
// expected outcome: refused with a message naming the file (and the pattern
// given), or accepted with a status flag raised, never a crash and never an
// exit 0 without a flag. Recordings go through both engines, as `run` drives
// them; configuration files through the offline check of `config set`;
// report files through the reader of `replay`.
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "lumavel/core/status.hpp"
#include "lumavel/host/config_text.hpp"
#include "lumavel/host/image_io.hpp"
#include "lumavel/host/report_file.hpp"
#include "lumavel/host/run_recording.hpp"
#include "recording_fixture.hpp"
// CppUTest last: its leak-detector macros redefine new.
#include "CppUTest/TestHarness.h"
#include "CppUTest/MemoryLeakWarningPlugin.h"

using namespace lumavel;
using namespace lumavel::host;

using fixture::replace_in;
using fixture::set_field;

namespace {

// ---- damage helpers --------------------------------------------------------

// Gyro rows kept where keep(t) holds.
void filter_gyro(const std::string& m, const std::function<bool(uint64_t)>& keep) {
  const std::vector<std::string> all = fixture::read_lines(m + "imu0/data.csv");
  std::vector<std::string> out = {all[0]};
  for (size_t i = 1; i < all.size(); ++i)
    if (keep(std::stoull(all[i].substr(0, all[i].find(','))))) out.push_back(all[i]);
  fixture::write_lines(m + "imu0/data.csv", out);
}

// Every gyro timestamp moved by `ns`.
void shift_gyro(const std::string& m, int64_t ns) {
  std::vector<std::string> l = fixture::read_lines(m + "imu0/data.csv");
  for (size_t i = 1; i < l.size(); ++i)
    l[i] = std::to_string(std::stoll(l[i].substr(0, l[i].find(','))) + ns) + l[i].substr(l[i].find(','));
  fixture::write_lines(m + "imu0/data.csv", l);
}

std::string image(int cam, int frame) {
  return "cam" + std::to_string(cam) + "/data/" + std::to_string(fixture::frame_time(fixture::Options{}, frame)) +
         ".png";
}

// ---- the recording corpus --------------------------------------------------

struct RecordingCase {
  const char* name;
  std::function<void(const std::string& mav0)> damage;  // mav0 ends with '/'
  const char* refused_with;  // a part of the message; nullptr: accepted, with `flag` raised
  uint16_t flag = 0;
};

const std::vector<RecordingCase>& recording_corpus() {
  static const std::vector<RecordingCase> c = {
      {"cam0 data.csv missing", [](const std::string& m) { std::remove((m + "cam0/data.csv").c_str()); },
       "cam0/data.csv: does not exist"},
      {"imu header renamed", [](const std::string& m) { replace_in(m + "imu0/data.csv", "w_RS_S_z", "w_z"); },
       "imu0/data.csv:1: header column 3"},
      {"extra column in a gyro row",
       [](const std::string& m) { set_field(m + "imu0/data.csv", 5, 6, "9.81,1"); }, "imu0/data.csv:5: expected 7 columns"},
      {"timestamp not an integer", [](const std::string& m) { set_field(m + "cam1/data.csv", 3, 0, "1.01e9"); },
       "cam1/data.csv:3: timestamp '1.01e9'"},
      {"timestamp goes back",
       [](const std::string& m) { set_field(m + "imu0/data.csv", 9, 0, "1000000000"); }, "is not after the previous one"},
      {"unpaired camera row", [](const std::string& m) { fixture::erase_line(m + "cam1/data.csv", 4); },
       "unpaired frame"},
      {"image file missing", [](const std::string& m) { std::remove((m + image(0, 6)).c_str()); }, "does not exist"},
      {"NaN gyro rate", [](const std::string& m) { set_field(m + "imu0/data.csv", 12, 3, "nan"); }, "not finite"},
      {"1e999 gyro rate", [](const std::string& m) { set_field(m + "imu0/data.csv", 12, 3, "1e999"); }, "beyond the largest number"},
      {"1e300 gyro rate", [](const std::string& m) { set_field(m + "imu0/data.csv", 20, 3, "1e300"); },
       "imu0/data.csv:20: column 'w_RS_S_z [rad s^-1]': 1e300 is beyond +-1000"},
      {"1e30 rad/s on an axis the rig does not use",
       [](const std::string& m) { set_field(m + "imu0/data.csv", 12, 1, "1e30"); },
       "imu0/data.csv:12: column 'w_RS_S_x [rad s^-1]': 1e30 is beyond +-1000"},
      {"-2e6 m/s^2 acceleration", [](const std::string& m) { set_field(m + "imu0/data.csv", 12, 5, "-2e6"); },
       "-2e6 is beyond +-100000, more than any IMU measures"},
      {"text in a gyro rate", [](const std::string& m) { set_field(m + "imu0/data.csv", 12, 2, "abc"); },
       "'abc' is not a number"},
      {"empty gyro field", [](const std::string& m) { set_field(m + "imu0/data.csv", 12, 1, ""); }, "is empty"},
      {"NUL inside a gyro rate",
       [](const std::string& m) { set_field(m + "imu0/data.csv", 12, 3, std::string("9\0" "0.0092", 8)); },
       "followed by a NUL byte"},
      {"NUL inside a ground-truth speed",
       [](const std::string& m) {
         set_field(m + "state_groundtruth_estimate0/data.csv", 6, 8, std::string("1\0" "7", 3));
       },
       "followed by a NUL byte"},
      // Beyond a physical bound (was: exit 0, "RMS error: 1e+06 m/s").
      {"1e6 m/s ground-truth velocity",
       [](const std::string& m) { set_field(m + "state_groundtruth_estimate0/data.csv", 6, 8, "1e6"); },
       "state_groundtruth_estimate0/data.csv:6: column 'v_RS_R_x [m s^-1]': 1e+06 m/s is beyond +-1000 m/s"},
      {"1e300 m ground-truth position",
       [](const std::string& m) { set_field(m + "state_groundtruth_estimate0/data.csv", 6, 1, "1e300"); },
       "state_groundtruth_estimate0/data.csv:6: column 'p_RS_R_x [m]': 1e+300 m is beyond +-1e+07 m"},
      {"1e9 rad/s ground-truth gyro bias",
       [](const std::string& m) { set_field(m + "state_groundtruth_estimate0/data.csv", 6, 13, "1e9"); },
       "state_groundtruth_estimate0/data.csv:6: column 'b_w_RS_S_z [rad s^-1]': 1e+09 is beyond +-1000"},
      {"no gyro samples",
       [](const std::string& m) { filter_gyro(m, [](uint64_t) { return false; }); }, "no gyro samples"},
      {"gyro 1000 s away", [](const std::string& m) { shift_gyro(m, 1000000000000ll); },
       "cover none of the intervals between the frames"},
      {"gyro ends 0.1 s before the first frame", [](const std::string& m) { shift_gyro(m, -500000000ll); },
       "cover none of the intervals"},
      {"sensor.yaml key missing", [](const std::string& m) { replace_in(m + "cam0/sensor.yaml", "intrinsics:", "intrinsicz:"); },
       "cam0/sensor.yaml: missing key 'intrinsics'"},
      {"sensor.yaml syntax", [](const std::string& m) { replace_in(m + "cam1/sensor.yaml", "resolution: [", "resolution: [["); },
       "cam1/sensor.yaml:"},
      {"T_BS not orthonormal", [](const std::string& m) { replace_in(m + "cam0/sensor.yaml", "data: [1", "data: [2"); },
       "T_BS: rotation part is not orthonormal"},
      {"T_BS a reflection", [](const std::string& m) { replace_in(m + "cam1/sensor.yaml", "data: [1", "data: [-1"); },
       "a reflection, not a rotation"},
      {"imu T_BS a reflection", [](const std::string& m) { replace_in(m + "imu0/sensor.yaml", "data: [1", "data: [-1"); },
       "imu0/sensor.yaml:"},
      {"camera looking up", [](const std::string& m) {
         replace_in(m + "cam0/sensor.yaml", "0, 0, 1, 0,\n         0, -1, 0, 0", "0, 1, 0, 0,\n         0, 0, 1, 0");
       },
       "cam0/sensor.yaml:5: T_BS: this camera looks along body"},
      {"fu = fv = 1e300", [](const std::string& m) { replace_in(m + "cam0/sensor.yaml", "intrinsics: [36, 36", "intrinsics: [1e300, 1e300"); },
       "cam0/sensor.yaml:17: intrinsics (at the working resolution): focal length fu"},
      {"cu = 1e6", [](const std::string& m) { replace_in(m + "cam1/sensor.yaml", "19.5, 14.5]", "1e6, 14.5]"); },
       "cam1/sensor.yaml:17: intrinsics: principal point cu = 1e+06 px must lie in [-width, 2 width]"},
      {"k1 = 1e10", [](const std::string& m) { replace_in(m + "cam0/sensor.yaml", "[0.01, ", "[1e10, "); },
       "cannot be inverted"},
      {"p2 = 20", [](const std::string& m) { replace_in(m + "cam1/sensor.yaml", "-0.0004]", "20]"); },
       "cam1/sensor.yaml:19: distortion_coefficients"},
      {"baseline 40 m", [](const std::string& m) { replace_in(m + "cam1/sensor.yaml", "0.04,", "40.04,"); },
       "baseline h = 40"},
      {"no baseline", [](const std::string& m) { replace_in(m + "cam1/sensor.yaml", "0.04,", "-0.04,"); },
       "cam0/sensor.yaml:5: T_BS: cam0 and cam1 are less than 0.1 mm apart"},
      {"truncated PNG",
       [](const std::string& m) {
         const std::string b = fixture::read_text(m + image(0, 9));
         fixture::write_text(m + image(0, 9), b.substr(0, b.size() - 30));
       },
       "corrupt PNG"},
      {"garbage PNG", [](const std::string& m) { fixture::write_text(m + image(1, 3), "\x89PNG\r\n\x1a\ngarbage"); },
       "corrupt PNG"},
      {"not an image", [](const std::string& m) { fixture::write_text(m + image(1, 5), "P5 40 30 255\n"); },
       "frame 5"},
      {"first frame of the wrong size",
       [](const std::string& m) {
         const std::vector<uint8_t> px(41 * 30, 100);
         write_png_gray(m + image(1, 0), px.data(), 41, 30);
       },
       "frame 0 of cam1 is 41x30"},
      // Found by the command-line campaign (cli_campaign.cpp).
      {"timestamp beyond int64 (a wrong distance, flagged only as a gyro gap)",
       [](const std::string& m) {
         for (const char* cam : {"cam0", "cam1"}) set_field(m + cam + "/data.csv", 13, 0, "9300000000000000000");
       },
       "cam0/data.csv:13: timestamp 9300000000000000000 is beyond 9223372036854775807 ns"},
      {"negative timestamp", [](const std::string& m) { set_field(m + "imu0/data.csv", 2, 0, "-1"); },
       "imu0/data.csv:2: timestamp -1 is negative"},
      {"ground truth with a header only (was: no ground truth, exit 0)",
       [](const std::string& m) {
         const std::string gt = m + "state_groundtruth_estimate0/data.csv";
         fixture::write_lines(gt, {fixture::read_lines(gt)[0]});
       },
       "state_groundtruth_estimate0/data.csv:2: no ground-truth samples"},
      {"T_BS given twice (the second was ignored)",
       [](const std::string& m) {
         const std::string y = m + "cam0/sensor.yaml";
         fixture::write_text(y, fixture::read_text(y) + "T_BS:\n  cols: 4\n  rows: 4\n  data: [1, 0, 0, 0.04, 0, 0, 1, "
                                                        "0, 0, -1, 0, 0, 0, 0, 0, 1]\n");
       },
       "cam0/sensor.yaml:20: key 'T_BS' is given again (first at line 5)"},
      {"fv = 1e12 (only the lens model reads it)",
       [](const std::string& m) { replace_in(m + "cam0/sensor.yaml", "intrinsics: [36, 36", "intrinsics: [36, 1e12"); },
       "cam0/sensor.yaml:17: intrinsics: fu = 36 px, fv = 1e+12 px: fv/fu must be 0.5..2"},
      {"cv = -1e5", [](const std::string& m) { replace_in(m + "cam1/sensor.yaml", "19.5, 14.5]", "19.5, -1e5]"); },
       "cam1/sensor.yaml:17: intrinsics: principal point cv = -100000 px must lie in [-height, 2 height]"},
      {"cam1 at another resolution",
       [](const std::string& m) { replace_in(m + "cam1/sensor.yaml", "resolution: [40, 30]", "resolution: [20, 15]"); },
       "cam1/sensor.yaml:15: resolution [20, 15] differs from"},
      {"baseline across body x",
       [](const std::string& m) { replace_in(m + "cam1/sensor.yaml", "0, 0, 1, 0,", "0, 0, 1, 3,"); },
       "cam0/sensor.yaml:5: T_BS: cam1's optical centre minus cam0's is (0.08, 3, 0) m"},
      // Accepted, and flagged.
      {"gyro stops early (frames beyond it flagged)",
       [](const std::string& m) { filter_gyro(m, [](uint64_t t) { return t < 1030000000ull; }); }, nullptr,
       kStatusGyroGap},
      {"gyro hole", [](const std::string& m) {
         filter_gyro(m, [](uint64_t t) { return t < 1020000000ull || t > 1090000000ull; });
       },
       nullptr, kStatusGyroGap},
      // Four samples in a row: one alone, out and back, is a read glitch,
      // replaced by its neighbours' mean and said (gyro_glitch.hpp).
      {"200 rad/s gyro samples for 4 periods (beyond the device's rail: saturated)",
       [](const std::string& m) {
         for (size_t line = 20; line < 24; ++line) set_field(m + "imu0/data.csv", line, 3, "200");
       },
       nullptr, kStatusSaturated},
      {"both cameras the same images",
       [](const std::string& m) {
         for (int f = 0; f < 12; ++f) fixture::write_text(m + image(1, f), fixture::read_text(m + image(0, f)));
       },
       nullptr, kStatusNoStereo},
  };
  return c;
}

// The first error `run` would report with `engine`, or "" with the flags of
// every frame OR-ed into `flags`.
std::string run_outcome(const std::string& rec_dir, EngineKind engine, uint16_t& flags) {
  flags = 0;
  try {
    const Recording rec = load_recording(rec_dir);
    RunOptions o;
    o.engine = engine;
    o.size = default_working_size(rec);
    o.decode_threads = 1;
    const RunResult r = run_recording(rec, o, nullptr);
    for (const TrackPoint& p : r.track) flags = static_cast<uint16_t>(flags | p.status);
    return "";
  } catch (const std::exception& e) {
    return e.what();
  }
}

}  // namespace

// The corpus table and the libraries' function-local statics outlive a test;
// AddressSanitizer (tools/test.sh) covers real leaks.
TEST_GROUP(Corpus) {
  fixture::TempDir dir;
  void setup() override { MemoryLeakWarningPlugin::saveAndDisableNewDeleteOverloads(); }
  void teardown() override { MemoryLeakWarningPlugin::restoreNewDeleteOverloads(); }
};

TEST(Corpus, EveryDamagedRecordingIsRefusedOrFlaggedByBothEngines) {
  int n = 0;
  for (const RecordingCase& c : recording_corpus()) {
    const std::string rec = dir.path() + "/rec" + std::to_string(n++);
    fixture::write_recording(rec);
    c.damage(rec + "/mav0/");
    for (EngineKind engine : {EngineKind::kFixed, EngineKind::kFloat}) {
      uint16_t flags = 0;
      const std::string e = run_outcome(rec, engine, flags);
      const std::string what = std::string(c.name) + " (" + engine_name(engine) + "): " + (e.empty() ? "accepted" : e);
      if (c.refused_with) {
        CHECK_TEXT(e.find(c.refused_with) != std::string::npos, what.c_str());
        CHECK_TEXT(e.find(rec + "/mav0/") != std::string::npos, what.c_str());  // names the file
      } else {
        CHECK_TEXT(e.empty(), what.c_str());
        CHECK_TEXT(flags & c.flag, what.c_str());
      }
    }
    std::filesystem::remove_all(rec);
  }
  CHECK(n > 30);
}

// ---- configuration files (config set --file, config check) ---------------

TEST(Corpus, EveryDamagedConfigurationFileIsRefusedNamingTheLine) {
  const struct {
    std::string text;
    const char* refused_with;
  } cases[] = {
      {"width=40\ntau_us=fast\n", "rig.cfg:2: tau_us = fast: not a whole number"},
      {std::string("tau_us=25\0" "0000\n", 15), "rig.cfg:1: \"tau_us=25\" is followed by a NUL byte"},
      {std::string("look=le\0" "ft\n", 11), "rig.cfg:1: \"look=le\" is followed by a NUL byte"},
      {"baseline_m=5\n", "rig.cfg:1: baseline_m = 5"},
      {"baseline_m=1e999\n", "rig.cfg:1: baseline_m"},
      {"width=40\nlens_cam0=0.1,0.2\n", "rig.cfg:2: lens_cam0"},
      {"lens_cam1=0.5,x\n", "rig.cfg:1: lens_cam1 value 2"},
      {"no_such_key=1\n", "rig.cfg:1: unknown configuration key"},
      {"width\n", "rig.cfg:1: \"width\" is not KEY=VALUE"},
      {"kernels=9:0.07\n", "rig.cfg:1: kernels"},
      {"width=99999999999999999999\n", "rig.cfg:1: width"},
      {"misalignment_rad=nan\n", "rig.cfg:1: misalignment_rad"},
  };
  fixture::TempDir d;
  for (const auto& c : cases) {
    const std::string path = d.path() + "/rig.cfg";
    fixture::write_text(path, c.text);
    std::string e;
    try {
      GivenSettings g;
      g.add_file(path);
      check_settings_offline(g);
    } catch (const std::exception& x) {
      e = x.what();
    }
    const size_t at = e.find("rig.cfg");
    const std::string shown = at == std::string::npos ? e : e.substr(at);
    CHECK_TEXT(shown.find(c.refused_with) == 0, (std::string(c.refused_with) + " <- got: " + e).c_str());
  }
}

// ---- report files (lumavel-read replay) ------------------------------------

TEST(Corpus, EveryDamagedReportFileIsRefusedNamingTheRecord) {
  fixture::TempDir d;
  const std::string path = d.path() + "/run.hidrep";
  const std::string magic(kReportFileMagic, 8);
  const struct {
    std::string bytes;
    const char* refused_with;
  } cases[] = {
      {"", "not a lumavel report file"},
      {"LMVHID2\n", "not a lumavel report file"},
      {magic + std::string(1, '\0'), "record 1"},
      {magic + "\x2a\x01\x01", "record 1"},
      {magic + std::string("\x02\x01\x01", 3) + "\x05\x01", "record 2"},
  };
  for (const auto& c : cases) {
    fixture::write_text(path, c.bytes);
    std::string e;
    try {
      ReportFileReader r(path);
      std::vector<uint8_t> rec;
      while (r.next(rec)) {
      }
    } catch (const std::exception& x) {
      e = x.what();
    }
    CHECK_TEXT(e.find(path) != std::string::npos, (std::to_string(c.bytes.size()) + " bytes: " + e).c_str());
    CHECK_TEXT(e.find(c.refused_with) != std::string::npos, e.c_str());
  }
}
