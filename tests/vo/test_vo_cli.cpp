// `lumavel-sim run --engine vo` as a user sees it.
#include <sys/wait.h>

#include <cstdlib>
#include <string>

#include "lumavel/host/run_recording.hpp"
#include "recording_fixture.hpp"
// CppUTest last: its leak-detector macros redefine new.
#include "CppUTest/TestHarness.h"

namespace {

struct Outcome {
  int code;
  std::string out, err;
};

}  // namespace

TEST_GROUP(VoCli) {
  fixture::TempDir dir;
  Outcome sim(const std::string& args) {
    const std::string out = dir.path() + "/stdout.txt", err = dir.path() + "/stderr.txt";
    const std::string cmd =
        "cd '" + dir.path() + "' && '" LUMAVEL_SIM_EXE "' " + args + " >'" + out + "' 2>'" + err + "'";
    const int status = std::system(cmd.c_str());
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, fixture::read_text(out), fixture::read_text(err)};
  }
};

TEST(VoCli, RunsAndWritesTheEstimatesCsv) {
  fixture::Options o;
  o.frames = 20;
  fixture::write_recording(dir.path() + "/rec", o);
  const Outcome r = sim("run rec --engine vo -o est.csv");
  LONGS_EQUAL(0, r.code);
  STRCMP_CONTAINS("vo engine, 40x30 working", r.err.c_str());
  STRCMP_CONTAINS("us/frame", r.err.c_str());
  STRCMP_CONTAINS("gyro offset: not learned (the vo engine takes the gyro as it reads)", r.err.c_str());
  const std::vector<std::string> lines = fixture::read_lines(dir.path() + "/est.csv");
  LONGS_EQUAL(21, lines.size());
  STRCMP_EQUAL(lumavel::host::kEstimatesHeader, lines[0].c_str());
}

TEST(VoCli, RefusesARigWithoutBaselineNamingTheFile) {
  fixture::write_recording(dir.path() + "/rec");
  // Move cam1 onto cam0 (x = -0.04): T_BS row 1 is on line 8 of sensor.yaml.
  const std::string yaml = dir.path() + "/rec/mav0/cam1/sensor.yaml";
  std::string text = fixture::read_text(yaml);
  const size_t at = text.find("0.04,");
  CHECK(at != std::string::npos);
  text.replace(at, 5, "-0.04,");
  fixture::write_text(yaml, text);
  const Outcome r = sim("run rec --engine vo");
  LONGS_EQUAL(1, r.code);
  // The rig rules every engine shares (check_rig_settings) refuse it first.
  STRCMP_CONTAINS("lumavel-sim run: error: rec/mav0/cam0/sensor.yaml:5: T_BS: cam0 and cam1 are less than 0.1 mm apart "
                  "along body x (no baseline)",
                  r.err.c_str());
}

TEST(VoCli, RefusesSizesBetweenTheBinnerAndTheSensor) {
  fixture::Options o;
  o.width = 240;
  o.height = 180;
  o.frames = 3;
  fixture::write_recording(dir.path() + "/rec", o);
  Outcome r = sim("run rec --engine vo --width 200 --height 150 --quiet");
  LONGS_EQUAL(1, r.code);
  STRCMP_CONTAINS("the vo engine runs at up to 160 columns (binned like lumavel's engines) or unbinned at the "
                  "sensor's resolution 240x180, not at 200x150",
                  r.err.c_str());
  r = sim("run rec --engine vo --width 240 --height 180 -o est.csv --quiet");
  LONGS_EQUAL(0, r.code);
  LONGS_EQUAL(4, fixture::read_lines(dir.path() + "/est.csv").size());
}
