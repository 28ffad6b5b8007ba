// lumavel-sim as a user sees it: exit codes, messages, files written.
#include <sys/wait.h>

#include <cstdlib>
#include <string>

#include "recording_fixture.hpp"
// CppUTest last: its leak-detector macros redefine new.
#include "CppUTest/TestHarness.h"

namespace {

struct Outcome {
  int code;
  std::string out, err;
};

}  // namespace

TEST_GROUP(Cli) {
  fixture::TempDir dir;
  // Runs `lumavel-sim ARGS` in the temp dir, capturing both streams.
  Outcome sim(const std::string& args) {
    const std::string out = dir.path() + "/stdout.txt", err = dir.path() + "/stderr.txt";
    const std::string cmd =
        "cd '" + dir.path() + "' && '" LUMAVEL_SIM_EXE "' " + args + " >'" + out + "' 2>'" + err + "'";
    const int status = std::system(cmd.c_str());
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, fixture::read_text(out), fixture::read_text(err)};
  }
  std::string rec(const fixture::Options& o = {}) { return fixture::write_recording(dir.path() + "/rec", o); }
  bool exists(const std::string& p) { return std::filesystem::exists(p); }
};

TEST(Cli, HelpAndVersion) {
  Outcome r = sim("--help");
  LONGS_EQUAL(0, r.code);
  STRCMP_CONTAINS("usage: lumavel-sim <command>", r.out.c_str());
  STRCMP_CONTAINS("  run ", r.out.c_str());
  r = sim("--version");
  LONGS_EQUAL(0, r.code);
  STRCMP_EQUAL("lumavel-sim " LUMAVEL_VERSION "\n", r.out.c_str());
  r = sim("run --help");
  LONGS_EQUAL(0, r.code);
  for (const char* opt : {"--engine fixed|float|vo", "-o, --output FILE", "--width W", "--height H", "--plot FILE.svg",
                          "--quiet", "exit status"})
    STRCMP_CONTAINS(opt, r.out.c_str());
}

TEST(Cli, UsageErrorsExitTwo) {
  Outcome r = sim("");
  LONGS_EQUAL(2, r.code);
  STRCMP_CONTAINS("usage:", r.err.c_str());
  r = sim("bogus");
  LONGS_EQUAL(2, r.code);
  STRCMP_CONTAINS("unknown command 'bogus'", r.err.c_str());
  r = sim("run");
  LONGS_EQUAL(2, r.code);
  STRCMP_CONTAINS("missing the recording folder REC", r.err.c_str());
  r = sim("run rec --engine turbo");
  LONGS_EQUAL(2, r.code);
  STRCMP_CONTAINS("--engine must be 'fixed', 'float' or 'vo', not 'turbo'", r.err.c_str());
  r = sim("run rec --width 12");
  LONGS_EQUAL(2, r.code);
  STRCMP_CONTAINS("--width must be in 16..160", r.err.c_str());
  r = sim("run rec --width 240");
  LONGS_EQUAL(2, r.code);
  STRCMP_CONTAINS("--width must be in 16..160 (the firmware core's limit; --engine vo goes up to the sensor's width)",
                  r.err.c_str());
  r = sim("run rec --engine vo --width 4096");
  LONGS_EQUAL(2, r.code);
  STRCMP_CONTAINS("--width must be in 16..2048 with --engine vo", r.err.c_str());
  r = sim("run rec --height=4x");
  LONGS_EQUAL(2, r.code);
  STRCMP_CONTAINS("--height '4x' is not an integer", r.err.c_str());
  r = sim("run rec --frobnicate");
  LONGS_EQUAL(2, r.code);
  STRCMP_CONTAINS("unknown option '--frobnicate'", r.err.c_str());
  r = sim("run rec -o");
  LONGS_EQUAL(2, r.code);
  STRCMP_CONTAINS("option -o needs a value", r.err.c_str());
}

TEST(Cli, MissingRecordingExitsOne) {
  const Outcome r = sim("run nowhere");
  LONGS_EQUAL(1, r.code);
  STRCMP_CONTAINS("lumavel-sim run: error: nowhere: recording folder does not exist", r.err.c_str());
}

TEST(Cli, BadGyroNamesFileAndLineAndLeavesNoOutput) {
  const std::string m = rec() + "/mav0/";  // messages show the path as given: rec/...
  fixture::set_line(m + "imu0/data.csv", 12, "1010000000,0.001,-0.002,nan,0.1,0,9.81");
  const Outcome r = sim("run rec -o est.csv");
  LONGS_EQUAL(1, r.code);
  STRCMP_CONTAINS("rec/mav0/imu0/data.csv:12: column 'w_RS_S_z [rad s^-1]'", r.err.c_str());
  CHECK(!exists(dir.path() + "/est.csv"));
}

TEST(Cli, BadFrameNamesTheFrameAndRemovesThePartialCsv) {
  const std::string m = rec() + "/mav0/";  // messages show the path as given: rec/...
  fixture::write_text(m + "cam0/data/1080000000.png", "not an image");
  fixture::write_text(dir.path() + "/previous.csv", "earlier results\n");
  Outcome r = sim("run rec -o previous.csv --quiet");
  LONGS_EQUAL(1, r.code);
  STRCMP_EQUAL("earlier results\n", fixture::read_text(dir.path() + "/previous.csv").c_str());  // not clobbered
  r = sim("run rec -o est.csv --quiet");
  LONGS_EQUAL(1, r.code);
  STRCMP_CONTAINS("frame 8 (t=1080000000 ns, cam0)", r.err.c_str());
  STRCMP_CONTAINS("rec/mav0/cam0/data/1080000000.png: not a PNG or binary PGM file", r.err.c_str());
  CHECK(!exists(dir.path() + "/est.csv"));
  size_t files = 0;  // no temporary file left behind either
  for (const auto& e : std::filesystem::directory_iterator(dir.path())) files += e.is_regular_file();
  LONGS_EQUAL(3, files);  // previous.csv, stdout.txt, stderr.txt
}

TEST(Cli, WritesThroughSpecialFilesWithoutReplacingThem) {
  rec();
  const std::string target = dir.path() + "/target.csv";
  fixture::write_text(target, "");
  std::filesystem::create_symlink(target, dir.path() + "/link.csv");
  const Outcome r = sim("run rec -o link.csv --quiet");
  LONGS_EQUAL(0, r.code);
  CHECK(std::filesystem::is_symlink(dir.path() + "/link.csv"));
  LONGS_EQUAL(13, fixture::read_lines(target).size());
  LONGS_EQUAL(0, sim("run rec -o /dev/null --quiet").code);
  CHECK(exists("/dev/null"));
}

TEST(Cli, RunWritesCsvSummaryAndPlot) {
  fixture::Options o;
  o.drop_frames = {4};
  rec(o);
  const Outcome r = sim("run rec");
  LONGS_EQUAL(0, r.code);
  const std::vector<std::string> lines = [&] {
    fixture::write_text(dir.path() + "/copy.csv", r.out);
    return fixture::read_lines(dir.path() + "/copy.csv");
  }();
  STRCMP_EQUAL("timestamp_ns,v_xb_mps,distance_m,heading_rad,status,gyro_offset_radps,v_direct_mps,texture", lines[0].c_str());
  LONGS_EQUAL(o.frames, lines.size());  // header + 11 frames (one dropped)
  CHECK(lines[1].rfind("1000000000,", 0) == 0);
  CHECK(lines[4].rfind("1030000000,", 0) == 0);
  CHECK(lines[5].rfind("1050000000,", 0) == 0);
  STRCMP_CONTAINS("rec: 11 frame pairs", r.err.c_str());
  STRCMP_CONTAINS("gaps: 1 frame gaps (about 1 pairs missing", r.err.c_str());
  STRCMP_CONTAINS("E (paper eq. 22", r.err.c_str());
  STRCMP_CONTAINS("excluded", r.err.c_str());
  STRCMP_CONTAINS("L1 error", r.err.c_str());
  STRCMP_CONTAINS("RMS error", r.err.c_str());
  STRCMP_CONTAINS("after the first 1.0 s", r.err.c_str());
  CHECK(r.err.find('\r') == std::string::npos);  // no progress when stderr is not a terminal
  const std::string svg = fixture::read_text(dir.path() + "/rec_estimates.svg");
  CHECK(svg.rfind("<svg", 0) == 0);
  STRCMP_CONTAINS("plot: rec_estimates.svg", r.err.c_str());
}

TEST(Cli, OutputFilePlotNextToItAndQuiet) {
  rec();
  std::filesystem::create_directory(dir.path() + "/out");
  Outcome r = sim("run rec/ -o out/est.csv --engine float --width 20 --height 10 --quiet");
  LONGS_EQUAL(0, r.code);
  STRCMP_EQUAL("", r.out.c_str());
  STRCMP_EQUAL("", r.err.c_str());
  LONGS_EQUAL(13, fixture::read_lines(dir.path() + "/out/est.csv").size());
  CHECK(exists(dir.path() + "/out/rec_estimates.svg"));
  r = sim("run rec/mav0 -o out/b.csv --plot mine.svg");
  LONGS_EQUAL(0, r.code);
  CHECK(exists(dir.path() + "/mine.svg"));
  STRCMP_CONTAINS("fixed engine, 40x30 working", r.err.c_str());
}

TEST(Cli, NoGroundTruthNoPlotUnlessAsked) {
  fixture::Options o;
  o.groundtruth = false;
  rec(o);
  Outcome r = sim("run rec -o est.csv");
  LONGS_EQUAL(0, r.code);
  STRCMP_CONTAINS("no ground truth", r.err.c_str());
  CHECK(!exists(dir.path() + "/rec_estimates.svg"));
  r = sim("run rec -o est.csv --plot p.svg");
  LONGS_EQUAL(0, r.code);
  CHECK(exists(dir.path() + "/p.svg"));
}

TEST(Cli, WorkingSizeLargerThanTheSensorIsRefused) {
  rec();
  const Outcome r = sim("run rec --width 64");
  LONGS_EQUAL(1, r.code);
  STRCMP_CONTAINS("cam0/sensor.yaml: cannot bin the 40x30 sensor up to the working resolution 64x30", r.err.c_str());
}

// The fixture's cameras carry a small radial-tangential distortion: corrected
// by default, read as pinhole with --ignore-distortion (other estimates).
TEST(Cli, IgnoreDistortionIsSaidAndChangesTheEstimates) {
  rec();
  Outcome r = sim("run --help");
  STRCMP_CONTAINS("--ignore-distortion", r.out.c_str());
  r = sim("run rec -o corrected.csv");
  LONGS_EQUAL(0, r.code);
  STRCMP_CONTAINS("lens: radial-tangential distortion corrected", r.err.c_str());
  r = sim("run rec -o ignored.csv --ignore-distortion");
  LONGS_EQUAL(0, r.code);
  STRCMP_CONTAINS("lens: distortion IGNORED (--ignore-distortion)", r.err.c_str());
  const std::vector<std::string> a = fixture::read_lines(dir.path() + "/corrected.csv"),
                                 b = fixture::read_lines(dir.path() + "/ignored.csv");
  LONGS_EQUAL(a.size(), b.size());
  CHECK(a != b);
}

// The summary ends with the gyro offset: the fixture's images move on every
// frame, so no standstill is seen and none is learned; the option says so.
TEST(Cli, GyroOffsetLearningIsReportedAndCanBeTurnedOff) {
  rec();
  Outcome r = sim("run --help");
  STRCMP_CONTAINS("--no-gyro-offset-learning", r.out.c_str());
  r = sim("run rec -o learning.csv");
  LONGS_EQUAL(0, r.code);
  STRCMP_CONTAINS("gyro offset: not learned (no standstill seen)", r.err.c_str());
  r = sim("run rec -o raw.csv --no-gyro-offset-learning");
  LONGS_EQUAL(0, r.code);
  STRCMP_CONTAINS("gyro offset: not learned (--no-gyro-offset-learning)", r.err.c_str());
  r = sim("run rec -o quiet.csv --quiet --no-gyro-offset-learning");
  LONGS_EQUAL(0, r.code);
  STRCMP_EQUAL("", r.err.c_str());
}
