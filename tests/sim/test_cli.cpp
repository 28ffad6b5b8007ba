// lumavel-sim as a user sees it: exit codes, messages, files written.
#include <sys/stat.h>
#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "lumavel/host/run_recording.hpp"
#include "recording_fixture.hpp"
// CppUTest last: its leak-detector macros redefine new.
#include "CppUTest/TestHarness.h"

namespace {

struct Outcome {
  int code;
  std::string out, err;
};

// The 1-based number of the line of `text` that starts with `key`, as text.
std::string line_of(const std::string& text, const std::string& key) {
  const size_t at = text.rfind("\n" + key) + 1;
  return std::to_string(1 + std::count(text.begin(), text.begin() + static_cast<long>(at), '\n'));
}

}  // namespace

TEST_GROUP(Cli) {
  fixture::TempDir dir;
  // Runs `lumavel-sim ARGS` in the temp dir, capturing both streams; killed
  // after `timeout_s` seconds when not 0 (exit code 124 then).
  Outcome sim(const std::string& args, int timeout_s = 0) { return tool(LUMAVEL_SIM_EXE, args, timeout_s); }
  // The same for another executable.
  Outcome tool(const std::string& exe, const std::string& args, int timeout_s = 0) {
    const std::string out = dir.path() + "/stdout.txt", err = dir.path() + "/stderr.txt";
    const std::string limit = timeout_s > 0 ? "timeout -s KILL " + std::to_string(timeout_s) + " " : "";
    const std::string cmd =
        "cd '" + dir.path() + "' && " + limit + "'" + exe + "' " + args + " >'" + out + "' 2>'" + err + "'";
    const int status = std::system(cmd.c_str());
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, fixture::read_text(out), fixture::read_text(err)};
  }
  std::string rec(const fixture::Options& o = {}) { return fixture::write_recording(dir.path() + "/rec", o); }
  bool exists(const std::string& p) { return std::filesystem::exists(p); }
};

TEST(Cli, HelpAndVersion) {
  Outcome r = sim("--help");
  LONGS_EQUAL(0, r.code);
  CHECK(r.out.rfind("Usage: lumavel-sim", 0) == 0);
  for (const char* cmd : {"run ", "render ", "reproduce ", "calibrate ", "import-slider "})
    STRCMP_CONTAINS(cmd, r.out.c_str());
  STRCMP_CONTAINS("Exit status: 0 done, 1 bad input or failure", r.out.c_str());
  r = sim("--version");
  LONGS_EQUAL(0, r.code);
  STRCMP_EQUAL("lumavel-sim " LUMAVEL_VERSION "\n", r.out.c_str());
  r = sim("run --help");
  LONGS_EQUAL(0, r.code);
  for (const char* opt : {"--engine fixed|float|vo", "-o,--output FILE", "--width W", "--height H", "--plot FILE.svg",
                          "--hid SPEC", "--hid-config FILE", "--hid-wait-ms N", "--hid-linger S", "--quiet",
                          "--ignore-distortion", "--no-gyro-offset-learning", "Exit status"})
    STRCMP_CONTAINS(opt, r.out.c_str());
}

// A usage error shows the arguments as a name is shown (shown_path's
// escapes): CLI11 and the validators put them in as they were typed, and
// 'lumavel-sim r<ESC>[2Jun' (a name a glob expanded, say) cleared the
// terminal with "unknown command 'r[2Jun'"; an option's value or an
// unexpected argument the same.
TEST(Cli, AUsageErrorShowsTheArgumentsEscaped) {
  Outcome r = sim("\"$(printf 'r\\033[2Jun')\"");
  LONGS_EQUAL(2, r.code);
  STRCMP_EQUAL("lumavel-sim: unknown command 'r\\x1B[2Jun'\n(see lumavel-sim --help)\n", r.err.c_str());
  r = sim("run rec --engine \"$(printf 'x\\033[2J')\"");
  LONGS_EQUAL(2, r.code);
  STRCMP_CONTAINS("--engine: unknown engine 'x\\x1B[2J' (expected fixed, float or vo)", r.err.c_str());
  r = sim("run rec \"$(printf -- '--w\\033[2J')\"");
  LONGS_EQUAL(2, r.code);
  STRCMP_CONTAINS("The following argument was not expected: --w\\x1B[2J\n", r.err.c_str());
  CHECK(r.err.find('\x1b') == std::string::npos);
}

// One style: every command's help starts with its usage line and ends with
// the exit status.
TEST(Cli, EveryCommandHasUsageFirstAndTheExitStatus) {
  for (const char* cmd : {"run", "render", "reproduce", "calibrate", "import-slider"}) {
    const Outcome r = sim(std::string(cmd) + " --help");
    LONGS_EQUAL(0, r.code);
    const std::string usage = std::string("Usage: lumavel-sim ") + cmd + " [OPTIONS]";
    CHECK_TEXT(r.out.rfind(usage, 0) == 0, cmd);
    STRCMP_CONTAINS("Exit status: 0 done, 1 bad input or failure", r.out.c_str());
    CHECK_TEXT(r.out.find("usage:") == std::string::npos, cmd);
  }
}

TEST(Cli, UsageErrorsExitTwo) {
  Outcome r = sim("");
  LONGS_EQUAL(2, r.code);
  STRCMP_CONTAINS("Usage: lumavel-sim", r.err.c_str());
  r = sim("bogus");
  LONGS_EQUAL(2, r.code);
  STRCMP_CONTAINS("lumavel-sim: unknown command 'bogus'\n(see lumavel-sim --help)", r.err.c_str());
  r = sim("run");
  LONGS_EQUAL(2, r.code);
  STRCMP_CONTAINS("lumavel-sim run: REC is required", r.err.c_str());
  r = sim("run rec --engine turbo");
  LONGS_EQUAL(2, r.code);
  STRCMP_CONTAINS("--engine: unknown engine 'turbo' (expected fixed, float or vo)", r.err.c_str());
  r = sim("run rec --width 12");
  LONGS_EQUAL(2, r.code);
  STRCMP_CONTAINS("--width: must be a whole number in 16..2048 (above 160 only with --engine vo), not '12'", r.err.c_str());
  r = sim("run rec --width 240");
  LONGS_EQUAL(2, r.code);
  STRCMP_CONTAINS("--width: must be a whole number in 16..160 (the firmware core's limit; --engine vo goes up to the "
                  "sensor's width), not '240'",
                  r.err.c_str());
  r = sim("run rec --engine vo --width 4096");
  LONGS_EQUAL(2, r.code);
  STRCMP_CONTAINS("--width: must be a whole number in 16..2048 (above 160 only with --engine vo), not '4096'",
                  r.err.c_str());
  // Steps the vo engine does not have (was: ignored, exit 0, without a word).
  r = sim("run rec --engine vo --lens-columns");
  LONGS_EQUAL(2, r.code);
  STRCMP_CONTAINS("--lens-columns: the vo engine has no column tables", r.err.c_str());
  r = sim("run rec --engine vo --photometric-balance");
  LONGS_EQUAL(2, r.code);
  STRCMP_CONTAINS("--photometric-balance: the vo engine balances no kernels", r.err.c_str());
  r = sim("run rec --engine vo --elevation-band");
  LONGS_EQUAL(2, r.code);
  STRCMP_CONTAINS("--elevation-band: the vo engine sums no columns (it tracks features); the option is for --engine "
                  "fixed or float",
                  r.err.c_str());
  r = sim("run rec --engine vo --width 40 --height 11");  // the option's fault, not sensor.yaml's
  LONGS_EQUAL(2, r.code);
  STRCMP_CONTAINS("--height: the vo engine tracks 2-D features and needs 12 rows or more, not '11'", r.err.c_str());
  r = sim("run rec --height=4x");
  LONGS_EQUAL(2, r.code);
  STRCMP_CONTAINS("--height: must be a whole number in 1..2048 (above 128 only with --engine vo), not '4x'", r.err.c_str());
  r = sim("run rec --frobnicate");
  LONGS_EQUAL(2, r.code);
  STRCMP_CONTAINS("not expected: --frobnicate", r.err.c_str());
  r = sim("run rec -o");
  LONGS_EQUAL(2, r.code);
  STRCMP_CONTAINS("--output: 1 required FILE missing", r.err.c_str());
  r = sim("run rec --hid bogus:x");
  LONGS_EQUAL(2, r.code);
  STRCMP_CONTAINS("--hid: unknown HID link \"bogus:x\"", r.err.c_str());
  r = sim("run rec --hid-linger 3");
  LONGS_EQUAL(2, r.code);
  STRCMP_CONTAINS("need --hid SPEC", r.err.c_str());
  r = sim("run rec --hid file:x --hid-linger -2");
  LONGS_EQUAL(2, r.code);
  STRCMP_CONTAINS("--hid-linger: must be a number of seconds >= 0, or -1 (until interrupted), not '-2'", r.err.c_str());
  r = sim("render a.yaml out --resolution 40by30");
  LONGS_EQUAL(2, r.code);
  STRCMP_CONTAINS("--resolution: must be WxH with W in 1..16384 and H in 1..16384 (e.g. 40x30), not '40by30'",
                  r.err.c_str());
  r = sim("render a.yaml out --resolution 8192x4096");  // was: rendered, then refused by run's check
  LONGS_EQUAL(2, r.code);
  STRCMP_CONTAINS("--resolution: 8192x4096 is 33554432 pixels: lumavel bins frames of at most 16777216 pixels",
                  r.err.c_str());
  // A recording's mav0 folder as the folder to write (was: rec/mav0/mav0 written, exit 0).
  r = sim("render a.yaml rec/mav0/");
  LONGS_EQUAL(2, r.code);
  STRCMP_CONTAINS("OUT: rec/mav0 is a recording's mav0 folder (the recording is written into a mav0 folder inside the "
                  "one given: this would make rec/mav0/mav0): give rec",
                  r.err.c_str());
  r = sim("import-slider data mav0");
  LONGS_EQUAL(2, r.code);
  STRCMP_CONTAINS("OUT_REC: mav0 is a recording's mav0 folder", r.err.c_str());
  STRCMP_CONTAINS("give .", r.err.c_str());
  r = sim("calibrate rec --max-shift 0");
  LONGS_EQUAL(2, r.code);
  STRCMP_CONTAINS("--max-shift: must be a number in (0, 20], not '0'", r.err.c_str());
  r = sim("calibrate rec --write-size 40x30");
  LONGS_EQUAL(2, r.code);
  STRCMP_CONTAINS("--write-size needs --write FILE", r.err.c_str());
  r = sim("reproduce --threads 0");
  LONGS_EQUAL(2, r.code);
  STRCMP_CONTAINS("--threads: must be a whole number in 1..64, not '0'", r.err.c_str());
  r = sim("reproduce --only 'no such study'");
  LONGS_EQUAL(2, r.code);
  STRCMP_CONTAINS("--only 'no such study': no study title contains it", r.err.c_str());
  // Was: the full run, replacing docs/results.md (here it stops at the missing scenarios, exit 1).
  r = sim("reproduce --only '' --scenarios no_such_folder --out out_only --doc out_only/results.md");
  LONGS_EQUAL(2, r.code);
  STRCMP_CONTAINS("--only: needs a part of a study title, not an empty one", r.err.c_str());
}

// An option's whole number has no leading zero: CLI11 converts integer
// options in base 0, so '--width 040' passed the range check as 40 and ran
// at 32 columns, exit 0. Refused, with the rule; a sign is a number's.
TEST(Cli, AWholeNumberWithALeadingZeroIsRefused) {
  const std::string r0 = rec();
  Outcome r = sim("run '" + r0 + "' -o est.csv --width 040");
  LONGS_EQUAL(2, r.code);
  STRCMP_CONTAINS("lumavel-sim run: --width: must be a whole number in 16..2048 (above 160 only with --engine vo), "
                  "written without a leading zero (octal to some readers), not '040'",
                  r.err.c_str());
  r = sim("render a.yaml out --resolution 040x30");
  LONGS_EQUAL(2, r.code);
  STRCMP_CONTAINS("--resolution: must be WxH with W in 1..16384 and H in 1..16384 (e.g. 40x30), written without a "
                  "leading zero (octal to some readers), not '040x30'",
                  r.err.c_str());
  r = sim("render a.yaml out --seed 010");
  LONGS_EQUAL(2, r.code);
  STRCMP_CONTAINS("--seed: must be a whole number in 0..9007199254740992, written without a leading zero", r.err.c_str());
  r = sim("run '" + r0 + "' -o est.csv --width +20");
  LONGS_EQUAL(0, r.code);
  STRCMP_CONTAINS(" 20x30 working", r.err.c_str());
  // A space is no part of a number: refused saying so (was: 'must be a whole
  // number in 16..2048, not ' 20'', the reason left to the quotes), in a
  // whole number, a decimal and a size alike.
  r = sim("run '" + r0 + "' -o est.csv --width ' 20'");
  LONGS_EQUAL(2, r.code);
  STRCMP_CONTAINS("lumavel-sim run: --width: must be a whole number in 16..2048 (above 160 only with --engine vo), "
                  "written without spaces (a space is no part of a number), not ' 20'",
                  r.err.c_str());
  r = sim("calibrate '" + r0 + "' --max-shift '5 '");
  LONGS_EQUAL(2, r.code);
  STRCMP_CONTAINS("--max-shift: must be a number in (0, 20], written without spaces (a space is no part of a number), "
                  "not '5 '",
                  r.err.c_str());
  r = sim("render a.yaml out --resolution '40x 30'");
  LONGS_EQUAL(2, r.code);
  STRCMP_CONTAINS("(e.g. 40x30), written without spaces (a space is no part of a number), not '40x 30'", r.err.c_str());
  r = sim("run '" + r0 + "' -o est.csv --width 0");
  LONGS_EQUAL(2, r.code);
  STRCMP_CONTAINS("not '0'", r.err.c_str());
}

// A number nearer 0 than any double, as a file's is (a77d867): '--exposure
// 1e-400' rendered with exposure 0, exit 0, and '--max-shift 1e-400' was
// told 'must be a number in (0, 20]', a rule the number meets.
TEST(Cli, ANumberNearerZeroThanAnyDoubleIsRefusedSayingSo) {
  Outcome r = sim("render a.yaml out --exposure 1e-400");
  LONGS_EQUAL(2, r.code);
  STRCMP_CONTAINS("lumavel-sim render: --exposure: must be a number in [0, 10], not '1e-400', which is nearer 0 than "
                  "the smallest number (about 2.2e-308)",
                  r.err.c_str());
  r = sim("calibrate nowhere --max-shift 1e-400");
  LONGS_EQUAL(2, r.code);
  STRCMP_CONTAINS("lumavel-sim calibrate: --max-shift: must be a number in (0, 20], not '1e-400', which is nearer 0 "
                  "than the smallest number (about 2.2e-308)",
                  r.err.c_str());
  r = sim("render a.yaml out --exposure 0e-400");  // exactly 0: a number like any other
  CHECK(r.err.find("--exposure") == std::string::npos);
}

TEST(Cli, MissingRecordingExitsOne) {
  Outcome r = sim("run nowhere");
  LONGS_EQUAL(1, r.code);
  STRCMP_CONTAINS("lumavel-sim run: error: nowhere: recording folder does not exist", r.err.c_str());
  fixture::write_text(dir.path() + "/afile", "x");
  r = sim("run afile");
  LONGS_EQUAL(1, r.code);
  STRCMP_CONTAINS("lumavel-sim run: error: afile: is a file, not a recording folder", r.err.c_str());
  r = sim("render . out");
  LONGS_EQUAL(1, r.code);
  STRCMP_CONTAINS("lumavel-sim render: error: .: is a folder, not a scenario file", r.err.c_str());
  r = sim("render '" LUMAVEL_SOURCE_DIR "/host_sim/scenarios/paper_sim_aligned.yaml' afile --duration 0.1 -q");
  LONGS_EQUAL(1, r.code);
  STRCMP_CONTAINS("lumavel-sim render: error: afile: is a file, not a folder to write the recording in", r.err.c_str());
}

// An output folder to be made under a symbolic link to nothing is refused
// before any work, saying so (was: reproduce's 'filesystem error: cannot
// create directories: File exists [lnk/sub/results]', render's
// 'lnk/sub/mav0/cam0/data: cannot create folder: File exists', a file that is
// not there). A read-only folder is said the same way ('no permission to
// write in its folder ro'), which root, who runs these tests, is not refused.
TEST(Cli, AnOutputFolderUnderALinkToNothingIsRefusedSayingSo) {
  std::filesystem::create_symlink(dir.path() + "/gone/away", dir.path() + "/lnk");
  Outcome r = sim("reproduce --only Lens --scenarios nowhere --out lnk/sub --doc p.md");
  LONGS_EQUAL(1, r.code);
  STRCMP_CONTAINS(("lumavel-sim reproduce: error: lnk/sub (--out): cannot be created: its folder lnk is a symbolic link "
                   "to " + dir.path() + "/gone/away, which does not exist").c_str(),
                  r.err.c_str());
  r = sim("reproduce --only Lens --scenarios nowhere --out out_r --doc p.md");  // the same, --out made
  CHECK(r.err.find("(--out)") == std::string::npos);
  r = sim("render '" LUMAVEL_SOURCE_DIR "/host_sim/scenarios/paper_sim_aligned.yaml' lnk/sub --duration 0.1 -q");
  LONGS_EQUAL(1, r.code);
  STRCMP_CONTAINS(("lumavel-sim render: error: lnk/sub: cannot be created: its folder lnk is a symbolic link to " +
                   dir.path() + "/gone/away, which does not exist").c_str(),
                  r.err.c_str());
  CHECK(!exists(dir.path() + "/gone"));
}

// An output named as long as a name may be (255 bytes) is written: its
// temporary name, the name and '.tmpPID', was longer, and the output was
// refused as 'VVV...csv (255 characters): cannot create the CSV: File name
// too long' ('--hid file:' named the temporary file, 'VVV....hid.tmp29720').
TEST(Cli, AnOutputNamedAsLongAsANameMayBeIsWritten) {
  rec();
  const std::string csv = std::string(251, 'v') + ".csv", hid = std::string(251, 'h') + ".hid",
                    svg = std::string(251, 'v') + ".svg";
  const Outcome r = sim("run rec -q -o " + csv + " --plot " + svg + " --hid file:" + hid);
  LONGS_EQUAL_TEXT(0, r.code, r.err.c_str());
  CHECK(exists(dir.path() + "/" + csv) && exists(dir.path() + "/" + svg) && exists(dir.path() + "/" + hid));
  CHECK(fixture::read_text(dir.path() + "/" + svg).find("<svg") != std::string::npos);
  CHECK(fixture::read_text(dir.path() + "/" + csv).rfind("timestamp_ns,", 0) == 0);
  size_t files = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir.path())) files += e.path().filename().string().size() > 250;
  LONGS_EQUAL(3, files);  // no temporary file left beside them
}

// 'render SCENARIO -' rendered into a new folder named '-' (exit 0): a
// recording is a folder, it cannot go to standard output.
// lumavel-bench-engines reads its options whole, as lumavel-sim does: sscanf
// took "40x30junk" as 40x30 and atoi "1e3" repeats as 1, exit 0; a size
// larger than a recording's sensor was left out of the table unsaid.
TEST(Cli, BenchEnginesReadsItsOptionsWholeAndSaysWhatItSkips) {
  Outcome r = tool(LUMAVEL_BENCH_ENGINES_EXE, "--size 40x30junk rec");
  LONGS_EQUAL(2, r.code);
  STRCMP_CONTAINS("lumavel-bench-engines: --size: must be WxH with W and H whole numbers in 1..2048, not '40x30junk'",
                  r.err.c_str());
  r = tool(LUMAVEL_BENCH_ENGINES_EXE, "--repeat 1e3 rec");
  LONGS_EQUAL(2, r.code);
  STRCMP_CONTAINS("lumavel-bench-engines: --repeat: must be a whole number in 1..1000, not '1e3'", r.err.c_str());
  rec();
  r = tool(LUMAVEL_BENCH_ENGINES_EXE, "--size 2000x30 rec");
  LONGS_EQUAL(0, r.code);
  STRCMP_CONTAINS("lumavel-bench-engines: rec: 2000x30 skipped: larger than its ", r.err.c_str());
}

TEST(Cli, RenderToDashIsRefused) {
  const Outcome r = sim("render '" LUMAVEL_SOURCE_DIR "/host_sim/scenarios/paper_sim_aligned.yaml' - --duration 0.1 -q");
  LONGS_EQUAL(1, r.code);
  STRCMP_CONTAINS("lumavel-sim render: error: - (OUT): '-' stands for standard output, where no recording is written: "
                  "give a folder name (./- for a folder of that name)", r.err.c_str());
  CHECK(!exists(dir.path() + "/-"));
}

// The preset option reads as one name in the help (it showed 'NAME:PRESET',
// which users took for a camera name and a preset) and its refusal says the
// option once (it said '--camera-mismatch: --camera-mismatch cam:x: ...').
TEST(Cli, RenderCameraMismatchTakesOnePresetName) {
  Outcome r = sim("render --help");
  LONGS_EQUAL(0, r.code);
  STRCMP_CONTAINS("--camera-mismatch PRESET ", r.out.c_str());
  CHECK(r.out.find("NAME:PRESET") == std::string::npos);
  r = sim("render a.yaml out --camera-mismatch cam:cheap_pair");
  LONGS_EQUAL(2, r.code);
  STRCMP_CONTAINS("--camera-mismatch: 'cam:cheap_pair' is not a preset (one of: ideal, cheap_pair, differing_pair, "
                  "cheap_pair_ae, tone_pair)", r.err.c_str());
}

// render's summary goes to standard output, progress to standard error; -q
// silences both, as its help says (it said 'no summary on standard error',
// where there was none).
TEST(Cli, RenderSummaryIsOnStandardOutputAndQuietSilencesIt) {
  const std::string scenario = "'" LUMAVEL_SOURCE_DIR "/host_sim/scenarios/paper_sim_aligned.yaml' --resolution 40x30 --duration 0.1";
  Outcome r = sim("render " + scenario + " out");
  LONGS_EQUAL(0, r.code);
  STRCMP_CONTAINS("out/mav0: 6 frame pairs (0 dropped) 40x30", r.out.c_str());
  CHECK(r.err.find("frame pairs") == std::string::npos);
  r = sim("render " + scenario + " out --force -q");
  LONGS_EQUAL(0, r.code);
  STRCMP_EQUAL("", r.out.c_str());
  STRCMP_EQUAL("", r.err.c_str());
  STRCMP_CONTAINS("-q,--quiet                  no progress on standard error, no summary on standard output",
                  sim("render --help").out.c_str());
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

// An output that is a FIFO nobody reads is refused after a short wait for a
// reader (was: run waited forever in open(), the work done and lost).
TEST(Cli, AFifoNobodyReadsIsRefusedNotWaitedOn) {
  rec();
  CHECK(::mkfifo((dir.path() + "/fifo").c_str(), 0600) == 0);
  for (const char* args : {"run rec --quiet -o fifo", "run rec --quiet -o est.csv --hid file:fifo",
                           "run rec --quiet -o est.csv --plot fifo"}) {
    const Outcome r = sim(args, 30);
    LONGS_EQUAL_TEXT(1, r.code, args);
    STRCMP_CONTAINS("fifo: cannot create", r.err.c_str());
    STRCMP_CONTAINS("is a FIFO (named pipe) that no process reads (none came within 2 s)", r.err.c_str());
    // Nothing more: '(check the directory exists and is writable)' followed it for --hid file:.
    STRCMP_CONTAINS("start its reader first, or write to a file\n", r.err.c_str());
    CHECK_TEXT(!exists(dir.path() + "/est.csv"), args);
  }
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
  STRCMP_EQUAL(lumavel::host::kEstimatesHeader, lines[0].c_str());
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
  STRCMP_CONTAINS("photometric match: the cameras taken as twins", r.err.c_str());  // the fixture's twins
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

// Run from inside the recording, as "." or "mav0": the plot and the summary
// still name the recording (they said "recording" and "mav0").
TEST(Cli, ARecordingRunFromInsideIsNamedByItsFolder) {
  rec();
  std::filesystem::create_directory(dir.path() + "/a");
  std::filesystem::create_directory(dir.path() + "/b");
  const std::string exe = std::string("'") + LUMAVEL_SIM_EXE + "'";
  Outcome r = tool("/bin/sh", "-c \"cd rec && " + exe + " run . -o ../a/e.csv && cd mav0 && " + exe +
                                  " run ../mav0 -o ../../b/e.csv && cd .. && " + exe + " run mav0 -o ../b/f.csv\"");
  LONGS_EQUAL(0, r.code);
  CHECK(exists(dir.path() + "/a/rec_estimates.svg"));
  CHECK(exists(dir.path() + "/b/rec_estimates.svg"));
  CHECK(!exists(dir.path() + "/a/recording_estimates.svg"));
  CHECK(!exists(dir.path() + "/b/mav0_estimates.svg"));
  STRCMP_CONTAINS("rec: 12 frame pairs", r.err.c_str());
  CHECK(r.err.find("mav0: 12 frame pairs") == std::string::npos);
  CHECK(r.err.find("recording: 12 frame pairs") == std::string::npos);
}

// The summary names the recording, the plot and the --hid file as every
// message does: a recording folder named 'e<ESC>[2Jrec' cleared the terminal
// with the summary's first line, its plot's name and the report file's too.
TEST(Cli, TheSummaryShowsTheNamesEscaped) {
  fixture::write_recording(dir.path() + "/e\x1b[2Jrec");
  const Outcome r = sim("run \"$(printf 'e\\033[2Jrec')\" -o est.csv --hid \"file:$(printf 'h\\033[2J.hidrep')\"");
  LONGS_EQUAL(0, r.code);
  STRCMP_CONTAINS("e\\x1B[2Jrec: 12 frame pairs", r.err.c_str());
  STRCMP_CONTAINS("plot: e\\x1B[2Jrec_estimates.svg\n", r.err.c_str());
  STRCMP_CONTAINS("hid: 12 reports sent through file:h\\x1B[2J.hidrep, 0 overruns", r.err.c_str());
  CHECK(r.err.find('\x1b') == std::string::npos);
}

TEST(Cli, PhotometricMatchCanBeTurnedOff) {
  rec();
  Outcome r = sim("run rec -o est.csv --no-photometric-match");
  LONGS_EQUAL(0, r.code);
  STRCMP_CONTAINS("photometric match: off (--no-photometric-match)", r.err.c_str());
}

TEST(Cli, ClipMatchIsReportedAndCanBeTurnedOff) {
  rec();
  Outcome r = sim("run rec -o est.csv");
  LONGS_EQUAL(0, r.code);
  STRCMP_CONTAINS("clip match: no frame where the brighter camera clipped on more than 2x the other's share of pixels", r.err.c_str());
  r = sim("run rec -o est.csv --no-clip-match");
  LONGS_EQUAL(0, r.code);
  STRCMP_CONTAINS("clip match: off (--no-clip-match)", r.err.c_str());
}

TEST(Cli, OutputToADeviceKeepsThePlotInTheCurrentFolder) {
  rec();
  Outcome r = sim("run rec -o /dev/null -q");
  LONGS_EQUAL(0, r.code);
  CHECK(exists(dir.path() + "/rec_estimates.svg"));
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
  const std::string yaml = fixture::read_text(rec() + "/mav0/cam0/sensor.yaml");
  const Outcome r = sim("run rec --width 64");
  LONGS_EQUAL(1, r.code);
  STRCMP_CONTAINS(("cam0/sensor.yaml:" + line_of(yaml, "resolution:") +
                   ": cannot bin the 40x30 sensor up to the working resolution 64x30")
                      .c_str(),
                  r.err.c_str());
}

// A line scan works at height 1; a --height beyond it is refused as a --width
// beyond the sensor is (was: --height 2 run at height 1, silently).
TEST(Cli, HeightLargerThanALineScanIsRefused) {
  fixture::Options o;
  o.height = 1;
  const std::string yaml = fixture::read_text(rec(o) + "/mav0/cam0/sensor.yaml");
  const Outcome r = sim("run rec --height 2");
  LONGS_EQUAL(1, r.code);
  STRCMP_CONTAINS(("cam0/sensor.yaml:" + line_of(yaml, "resolution:") +
                   ": cannot bin the 40x1 sensor up to the working resolution 40x2")
                      .c_str(),
                  r.err.c_str());
  LONGS_EQUAL(0, sim("run rec --height 1 -q -o /dev/null").code);
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

// The default working size is 40x30, or the sensor's own size when smaller:
// a 20x15 recording runs with no options, and the summary says where the
// size came from.
TEST(Cli, DefaultWorkingSizeIsTheSensorsWhenSmaller) {
  fixture::Options o;
  o.width = 20;
  o.height = 15;
  rec(o);
  Outcome r = sim("run rec -o est.csv");
  LONGS_EQUAL(0, r.code);
  STRCMP_CONTAINS("20x15 working (the default 40x30 cut to the 20x15 sensor)", r.err.c_str());
  r = sim("run rec -o est.csv --height 10");
  LONGS_EQUAL(0, r.code);
  STRCMP_CONTAINS("20x10 working,", r.err.c_str());
}

TEST(Cli, DefaultWorkingSizeOnALargerSensorIs40x30) {
  fixture::Options o;
  o.width = 64;
  o.height = 48;
  rec(o);
  Outcome r = sim("run rec -o est.csv");
  LONGS_EQUAL(0, r.code);
  STRCMP_CONTAINS("40x30 working (the default)", r.err.c_str());
  r = sim("run rec -o est.csv --width 64");
  LONGS_EQUAL(0, r.code);
  STRCMP_CONTAINS("64x30 working,", r.err.c_str());
}

// The summary counts the frames each flag was raised on, and a figure that
// cannot be computed says why instead of printing nan.
TEST(Cli, SummaryCountsFlagsAndNeverPrintsNan) {
  fixture::Options o;
  o.speed = 0;  // standing still: E is undefined
  rec(o);
  const Outcome r = sim("run rec -o est.csv");
  LONGS_EQUAL(0, r.code);
  STRCMP_CONTAINS("flags, frames of 12:", r.err.c_str());
  STRCMP_CONTAINS("CONVERGING 12 (converging)", r.err.c_str());
  STRCMP_CONTAINS("E (paper eq. 22): no figure: |V| < 0.05 m/s on every frame", r.err.c_str());
  STRCMP_CONTAINS("L1 error: no figure: the true speed is 0 throughout", r.err.c_str());
  STRCMP_CONTAINS("after the first 1.0 s: no figure: the run lasts 0.110 s", r.err.c_str());
  CHECK(r.err.find("nan") == std::string::npos);
  CHECK(r.err.find("inf ") == std::string::npos);
}

// A rig setting the firmware cannot take names the file it came from, the
// value (in %g, not 300 digits) and the rule.
TEST(Cli, ConfigurationRefusalsNameTheFileTheValueAndTheRule) {
  const std::string yaml = rec() + "/mav0/cam1/sensor.yaml";
  // The cameras 100 m either side of the body origin, as far as a sensor.yaml may put them.
  fixture::replace_in(dir.path() + "/rec/mav0/cam0/sensor.yaml", "-0.04,", "-99.92,");
  std::string text = fixture::read_text(yaml);
  text.replace(text.find("0.04,"), 5, "100,");
  fixture::write_text(yaml, text);
  Outcome r = sim("run rec -o est.csv");
  LONGS_EQUAL(1, r.code);
  STRCMP_CONTAINS(("rec/mav0/cam0/sensor.yaml:" + line_of(text, "T_BS:") + " and cam1/sensor.yaml:" +
                   line_of(text, "T_BS:") + ": T_BS").c_str(),
                  r.err.c_str());
  STRCMP_CONTAINS("baseline h = 199.92 m does not fit its fixed-point format (|value| < 128 m)", r.err.c_str());
  std::filesystem::remove_all(dir.path() + "/rec");
  const std::string yaml0 = rec() + "/mav0/cam0/sensor.yaml";
  text = fixture::read_text(yaml0);
  const size_t in = text.find("intrinsics: [") + 13;
  text.replace(in, text.find(',', text.find(',', in) + 1) - in, "1e300, 1e300");  // fu and fv: square pixels
  fixture::write_text(yaml0, text);
  r = sim("run rec -o est.csv");
  LONGS_EQUAL(1, r.code);
  STRCMP_CONTAINS(("rec/mav0/cam0/sensor.yaml:" + line_of(text, "intrinsics:") +
                   ": intrinsics (at the working resolution): focal length fu = 1e+300 px does not fit").c_str(),
                  r.err.c_str());
  fixture::Options slow;
  slow.t0 = 5000000000ull;
  slow.frame_dt = 2000000000ull;  // 2 s between frames
  slow.frames = 4;
  std::filesystem::remove_all(dir.path() + "/rec");
  rec(slow);
  r = sim("run rec -o est.csv");
  LONGS_EQUAL(1, r.code);
  STRCMP_CONTAINS("rec/mav0/cam0/data.csv: the median interval between frames: frame period = 2 s: frame period "
                  "must be 1 ms..1 s",
                  r.err.c_str());
}

// A quick or partial reproduce never replaces the committed full page,
// whatever the current folder (the test runs in a temporary one).
TEST(Cli, QuickReproduceNeverWritesTheCommittedPage) {
  const std::string page = LUMAVEL_SOURCE_DIR "/docs/results.md";
  const std::string before = fixture::read_text(page);
  Outcome r = sim("reproduce --quick --doc '" + page + "'");
  LONGS_EQUAL(2, r.code);
  STRCMP_CONTAINS("a --quick run never replaces the full results page docs/results.md", r.err.c_str());
  r = sim("reproduce --only Lens --doc '" LUMAVEL_SOURCE_DIR "/host_sim/../docs/results.md'");
  LONGS_EQUAL(2, r.code);
  STRCMP_CONTAINS("a --only run never replaces the full results page", r.err.c_str());
  STRCMP_EQUAL(before.c_str(), fixture::read_text(page).c_str());
  r = sim("reproduce --help");
  LONGS_EQUAL(0, r.code);
  STRCMP_CONTAINS("never\nin the current folder", r.out.c_str());
  STRCMP_CONTAINS("--quick", r.out.c_str());
}

// reproduce's page to a FIFO nobody reads is refused after 2 s, as run's
// outputs are (was: waited on in open() for ever, the studies done). The
// real-recording section is the shortest: a few seconds, or skipped where
// the slider_depth data is not there.
TEST(Cli, ReproducePageToAFifoNobodyReadsIsRefused) {
  CHECK(::mkfifo((dir.path() + "/page.md").c_str(), 0600) == 0);
  const Outcome r = sim("reproduce --only 'Real recording' --out out_r --doc page.md", 120);
  LONGS_EQUAL(1, r.code);
  STRCMP_CONTAINS("lumavel-sim reproduce: error: page.md: cannot create the page (--doc): is a FIFO (named pipe) that "
                  "no process reads (none came within 2 s)",
                  r.err.c_str());
}

// The plot a run writes is an SVG that a real renderer draws (rsvg-convert,
// Debian librsvg2-bin): what a user converts to look at it.
TEST(Cli, ThePlotRendersToAPng) {
  fixture::Options o;
  o.frames = 150;  // 1.5 s: an error panel with the first second clipped
  o.drop_frames = {60, 61};
  rec(o);
  LONGS_EQUAL(0, sim("run rec -o est.csv --quiet").code);
  const std::string svg = dir.path() + "/rec_estimates.svg", png = dir.path() + "/plot.png";
  const std::string cmd = "rsvg-convert '" + svg + "' -o '" + png + "' 2>'" + dir.path() + "/rsvg.err'";
  LONGS_EQUAL(0, std::system(cmd.c_str()));
  const std::string bytes = fixture::read_text(png);
  CHECK(bytes.size() > 10000);
  CHECK(bytes.compare(1, 3, "PNG") == 0);
  STRCMP_EQUAL("", fixture::read_text(dir.path() + "/rsvg.err").c_str());
  STRCMP_CONTAINS(">FRAME_GAP<", fixture::read_text(svg).c_str());
}

// '--plot -' is standard output, as '-o -' is (was: the SVG written to a file
// named '-', exit 0); with the CSV there too it is refused before the run.
TEST(Cli, PlotDashIsStandardOutput) {
  rec();
  Outcome r = sim("run rec --quiet -o est.csv --plot -");
  LONGS_EQUAL(0, r.code);
  CHECK(r.out.rfind("<svg", 0) == 0);
  CHECK(!exists(dir.path() + "/-"));
  CHECK(exists(dir.path() + "/est.csv"));
  for (const char* args : {"run rec --quiet --plot -", "run rec --quiet -o - --plot -"}) {
    r = sim(args);
    LONGS_EQUAL_TEXT(2, r.code, args);
    STRCMP_CONTAINS("- (--plot): standard output takes the CSV already (no -o, or -o -)", r.err.c_str());
    STRCMP_EQUAL_TEXT("", r.out.c_str(), args);
    CHECK_TEXT(!exists(dir.path() + "/-"), args);
  }
}

// A symbolic link whose target is not there is written through: refused
// before the run when that target cannot be made (was: passed the check,
// then 'gone.csv: cannot create the CSV: No such file or directory'); one
// whose target can be made is written through as before.
TEST(Cli, AnOutputThatIsADanglingLinkIsJudgedByItsTarget) {
  rec();
  std::filesystem::create_symlink("nowhere/x.csv", dir.path() + "/gone.csv");
  Outcome r = sim("run rec -o gone.csv");
  LONGS_EQUAL(1, r.code);
  STRCMP_CONTAINS("lumavel-sim run: error: gone.csv (-o): is a symbolic link to nowhere/x.csv, which cannot be created: "
                  "its folder nowhere does not exist",
                  r.err.c_str());
  CHECK(r.err.find("frame pairs") == std::string::npos);  // refused before the run
  std::filesystem::create_symlink("made.csv", dir.path() + "/link.csv");
  r = sim("run rec -q -o link.csv");
  LONGS_EQUAL(0, r.code);
  CHECK(fixture::read_text(dir.path() + "/made.csv").rfind("timestamp_ns,", 0) == 0);
  // render's OUT/mav0 a dangling link: there, as an OUT/mav0 folder is (was:
  // 'out/mav0/cam0/data: cannot create folder: File exists', --force or not).
  std::filesystem::create_directory(dir.path() + "/out");
  std::filesystem::create_symlink("moved", dir.path() + "/out/mav0");
  const std::string render = "render '" LUMAVEL_SOURCE_DIR "/host_sim/scenarios/paper_sim_aligned.yaml' out --resolution 40x30 --duration 0.1 -q";
  r = sim(render);
  LONGS_EQUAL(1, r.code);
  STRCMP_CONTAINS("lumavel-sim render: error: out/mav0 already exists (use --force to replace it)", r.err.c_str());
  LONGS_EQUAL(0, sim(render + " --force").code);
  CHECK(std::filesystem::is_directory(dir.path() + "/out/mav0/cam0/data"));
}

// An output that cannot be written is refused before the work that fills it
// (a 30 s calibration, a run), naming the option, the path and the reason.
TEST(Cli, UnwritableOutputsAreRefusedBeforeTheWork) {
  rec();
  std::filesystem::create_directory(dir.path() + "/adir");
  Outcome r = sim("run rec -o adir");
  LONGS_EQUAL(1, r.code);
  STRCMP_CONTAINS("lumavel-sim run: error: adir (-o): is a folder, not a CSV file", r.err.c_str());
  CHECK(r.err.find("frame pairs") == std::string::npos);  // refused before the run
  r = sim("run rec -o est.csv --plot nowhere/p.svg");
  LONGS_EQUAL(1, r.code);
  STRCMP_CONTAINS("nowhere/p.svg (--plot): cannot be created: its folder nowhere does not exist", r.err.c_str());
  CHECK(!exists(dir.path() + "/est.csv"));
  // The plot is an SVG drawing: another extension is refused before the run (it was written as SVG, unsaid).
  r = sim("run rec -o est.csv --plot p.png");
  LONGS_EQUAL(1, r.code);
  STRCMP_CONTAINS("p.png (--plot): the plot is an SVG drawing, not .png: give a name ending in .svg", r.err.c_str());
  CHECK(!exists(dir.path() + "/est.csv") && !exists(dir.path() + "/p.png"));
  r = sim("run rec -o est.csv --hid file:r.hidrep --hid-config adir");
  LONGS_EQUAL(1, r.code);
  STRCMP_CONTAINS("adir (--hid-config): is a folder, not a configuration file", r.err.c_str());
  r = sim("run rec -o est.csv --hid file:r.hidrep --hid-config /dev/zero");
  LONGS_EQUAL(1, r.code);
  STRCMP_CONTAINS("/dev/zero (--hid-config): is a character device node, not a configuration file", r.err.c_str());
  r = sim("run rec -o est.csv --hid file:adir");
  LONGS_EQUAL(1, r.code);
  STRCMP_CONTAINS("adir (--hid file:): is a folder, not a report file", r.err.c_str());
  r = sim("calibrate rec --write adir");
  LONGS_EQUAL(1, r.code);
  STRCMP_CONTAINS("lumavel-sim calibrate: error: adir (--write): is a folder, not a configuration file", r.err.c_str());
  CHECK(r.err.find("registering") == std::string::npos);
  // '-' is standard output only where an output can go there (-o, --plot):
  // elsewhere a file named '-' was made, exit 0, unsaid.
  r = sim("run rec -o est.csv --hid file:-");
  LONGS_EQUAL(1, r.code);
  STRCMP_CONTAINS("- (--hid file:): '-' stands for standard output, where no report file is written: give a file name",
                  r.err.c_str());
  r = sim("calibrate rec --write -");
  LONGS_EQUAL(1, r.code);
  STRCMP_CONTAINS("- (--write): '-' stands for standard output, where no configuration file is written", r.err.c_str());
  CHECK(!exists(dir.path() + "/-") && !exists(dir.path() + "/est.csv"));
  // reproduce's page and folders, before its studies (was: every study run, then 'cannot write');
  // --scenarios nowhere: without the check the run stops at its first scenario instead.
  fixture::write_text(dir.path() + "/afile", "x");
  for (const auto& [args, said] : std::vector<std::pair<std::string, std::string>>{
           {"--out out_r --doc adir", "adir (--doc): is a folder, not a results page"},
           {"--out out_r --doc page", "page (--doc): has no extension"},
           // (was: nowhere/ and nowhere/p/ made, the page written there)
           {"--out out_r --doc nowhere/p.md", "nowhere/p.md (--doc): cannot be created: its folder nowhere does not exist"},
           {"--out afile --doc p.md", "afile (--out): is a file, not a folder for the recordings and plots"},
           {"--out out_r --doc afile.md", "afile (the plots of --doc): is a file, not a folder for the page's plots"},
           // (was: its section skipped as "not there", exit 0; only the default may be missing)
           {"--out out_r --doc p.md --slider-data nowhere", "nowhere (--slider-data): does not exist"},
           {"--out out_r --doc p.md --slider-data afile", "afile (--slider-data): is a file, not a dataset folder"},
           // (was: 'reproduce: page ...' said, then 'nowhere/paper_sim_aligned.yaml: does not exist', the option unnamed)
           {"--out out_r --doc p.md", "nowhere (--scenarios): does not exist"}}) {
    r = sim("reproduce --only Lens --scenarios nowhere " + args);
    LONGS_EQUAL_TEXT(1, r.code, args.c_str());
    STRCMP_CONTAINS(said.c_str(), r.err.c_str());
  }
}

// Below the 160 columns calibrate is validated at, it says so, one sentence a
// line, and why the columns are fewer (the sensor's width or --width).
TEST(Cli, CalibrateWarnsWhenCoarserThanValidated) {
  rec();
  Outcome r = sim("calibrate rec -q");
  STRCMP_CONTAINS("calibrate: warning: registering at 40 columns (the sensor's width: rec has 40 columns)\n"
                  "calibrate: warning: calibrate is validated at 160 columns (docs/results.md); on coarser images\n"
                  "  its estimate and its uncertainty are less reliable\n",
                  r.err.c_str());
  r = sim("calibrate rec -q --width 20");
  STRCMP_CONTAINS("calibrate: warning: registering at 20 columns (--width)\n", r.err.c_str());
}

// --width wider than the sensor is refused as run refuses it, one rule (was:
// registered at the sensor's 40 columns with a warning, where run exits 1).
TEST(Cli, CalibrateRefusesAWidthBeyondTheSensorAsRunDoes) {
  rec();
  const std::string said = "rec/mav0/cam0/sensor.yaml:";
  Outcome r = sim("run rec -q -o est.csv --width 80");
  LONGS_EQUAL(1, r.code);
  STRCMP_CONTAINS("cannot bin the 40x30 sensor up to the working resolution 80x30", r.err.c_str());
  r = sim("calibrate rec -q --width 80");
  LONGS_EQUAL(1, r.code);
  STRCMP_CONTAINS(said.c_str(), r.err.c_str());
  // calibrate has no --height: its hint names --width alone (was: '--width/--height').
  STRCMP_CONTAINS("cannot bin the 40x30 sensor up to the working resolution 80x30 (choose a smaller --width)\n",
                  r.err.c_str());
  r = sim("run rec -q -o est.csv --width 80");
  STRCMP_CONTAINS("(choose a smaller --width/--height)\n", r.err.c_str());
}

// The same short options in every command that has them.
TEST(Cli, QuietIsDashQEverywhere) {
  for (const char* cmd : {"run", "render", "calibrate"})
    STRCMP_CONTAINS("-q,--quiet", sim(std::string(cmd) + " --help").out.c_str());
}

// calibrate reads a rig by run's rules: what run refuses (a principal point
// of 1e6 px, which used to overflow an int and crash calibrate; a 40 m
// baseline; a 2 s frame period), calibrate refuses with the same message.
TEST(Cli, CalibrateRefusesWhatRunRefuses) {
  auto refused_alike = [&](const char* what) {
    const Outcome run = sim("run rec -o est.csv --quiet"), cal = sim("calibrate rec --quiet");
    LONGS_EQUAL_TEXT(1, run.code, what);
    LONGS_EQUAL_TEXT(1, cal.code, what);
    const std::string why = run.err.substr(run.err.find("error: ") + 7);
    CHECK_TEXT(!why.empty(), what);
    STRCMP_CONTAINS(why.substr(0, why.find(" = ")).c_str(), cal.err.c_str());
    CHECK_TEXT(cal.out.find("misalignment:") == std::string::npos, what);
  };
  const std::string yaml0 = rec() + "/mav0/cam0/sensor.yaml", yaml1 = dir.path() + "/rec/mav0/cam1/sensor.yaml";
  const std::string intact0 = fixture::read_text(yaml0), intact1 = fixture::read_text(yaml1);
  std::string t = intact0;
  t.replace(t.find("19.5, 14.5]"), 4, "1e6");  // cu
  fixture::write_text(yaml0, t);
  refused_alike("cu = 1e6");
  STRCMP_CONTAINS("rec/mav0/cam0/sensor.yaml:17: intrinsics: principal point cu = 1e+06 px",
                  sim("calibrate rec --quiet").err.c_str());
  t = intact0;
  const size_t fu = t.find("intrinsics: [") + 13;
  t.replace(fu, t.find(',', t.find(',', fu) + 1) - fu, "1e300, 1e300");  // fu and fv: square pixels
  fixture::write_text(yaml0, t);
  refused_alike("fu = 1e300");
  fixture::write_text(yaml0, intact0);
  t = intact1;
  t.replace(t.find("0.04,"), 5, "40.04,");
  fixture::write_text(yaml1, t);
  refused_alike("baseline 40 m");
  STRCMP_CONTAINS("baseline h = 40", sim("calibrate rec --quiet").err.c_str());
  fixture::Options slow;
  slow.t0 = 5000000000ull;
  slow.frame_dt = 2000000000ull;  // 2 s between frames
  slow.frames = 4;
  std::filesystem::remove_all(dir.path() + "/rec");
  rec(slow);
  refused_alike("frame period 2 s");
  STRCMP_CONTAINS("frame period must be 1 ms..1 s", sim("calibrate rec --quiet").err.c_str());
}

// Every engine reads a rig by the same rules: the vo engine accepted a 40 m
// baseline and cu = 1e6 px (exit 0, a meaningless V) that fixed and float refuse.
TEST(Cli, EveryEngineRefusesTheSameRig) {
  const std::string yaml0 = rec() + "/mav0/cam0/sensor.yaml", yaml1 = dir.path() + "/rec/mav0/cam1/sensor.yaml";
  const std::string intact0 = fixture::read_text(yaml0), intact1 = fixture::read_text(yaml1);
  std::string t = intact1;
  t.replace(t.find("0.04,"), 5, "40.04,");
  fixture::write_text(yaml1, t);
  for (const char* engine : {"fixed", "float", "vo"}) {
    const Outcome r = sim(std::string("run rec -o est.csv --quiet --engine ") + engine);
    LONGS_EQUAL_TEXT(1, r.code, engine);
    STRCMP_CONTAINS("T_BS (the baseline is cam1's x minus cam0's): baseline h = 40", r.err.c_str());
  }
  fixture::write_text(yaml1, intact1);
  t = intact0;
  t.replace(t.find("19.5, 14.5]"), 4, "1e6");
  fixture::write_text(yaml0, t);
  for (const char* engine : {"fixed", "float", "vo"}) {
    const Outcome r = sim(std::string("run rec -o est.csv --quiet --engine ") + engine);
    LONGS_EQUAL_TEXT(1, r.code, engine);
    STRCMP_CONTAINS("rec/mav0/cam0/sensor.yaml:17: intrinsics: principal point cu = 1e+06 px", r.err.c_str());
  }
  CHECK(!exists(dir.path() + "/est.csv"));
}

// Outputs are complete or absent. A run that failed mid-way used to leave a
// header and the rows before the bad frame on standard output, a partial
// --hid file: report file that replay accepted, and a CSV when the plot
// could not be written.
TEST(Cli, ARunThatFailsMidwayLeavesNoPartialOutput) {
  const std::string m = rec() + "/mav0/";
  fixture::write_text(m + "cam0/data/1080000000.png", "not an image");  // frame 8 of 12
  Outcome r = sim("run rec --quiet");
  LONGS_EQUAL(1, r.code);
  STRCMP_CONTAINS("frame 8 (t=1080000000 ns, cam0)", r.err.c_str());
  STRCMP_EQUAL("", r.out.c_str());  // no header, no rows
  r = sim("run rec -o est.csv --quiet --hid file:run.hidrep");
  LONGS_EQUAL(1, r.code);
  CHECK(!exists(dir.path() + "/est.csv"));
  CHECK(!exists(dir.path() + "/run.hidrep"));
  size_t files = 0;  // no temporary file left behind either
  for (const auto& e : std::filesystem::directory_iterator(dir.path())) files += e.is_regular_file();
  LONGS_EQUAL(2, files);  // stdout.txt, stderr.txt
}

TEST(Cli, APlotThatCannotBeWrittenLeavesNoCsv) {
  rec();
  const Outcome r = sim("run rec -o est.csv --quiet --plot no/such/folder/p.svg --hid file:run.hidrep");
  LONGS_EQUAL(1, r.code);
  STRCMP_CONTAINS("no/such/folder/p.svg (--plot): cannot be created: its folder no/such/folder does not exist", r.err.c_str());
  CHECK(!exists(dir.path() + "/est.csv"));
  CHECK(!exists(dir.path() + "/run.hidrep"));
}

TEST(Cli, AGoodRunWritesItsHidReportFileWhole) {
  rec();
  const Outcome r = sim("run rec -o est.csv --quiet --hid file:run.hidrep");
  LONGS_EQUAL(0, r.code);
  const std::string bytes = fixture::read_text(dir.path() + "/run.hidrep");
  CHECK(bytes.rfind("LMVHID1\n", 0) == 0);
  CHECK(bytes.size() > 8 + 12 * 2);  // one report per frame at least
  LONGS_EQUAL(0, sim("run rec --quiet --hid file:/dev/null -o /dev/null").code);  // in place, never replaced
  CHECK(exists("/dev/null"));
}

// calibrate suggests a value for a board only when its uncertainty is at
// most 0.1 deg: at 40 columns it used to print the config set command for an
// estimate 0.36 deg off with a quoted 0.04 deg.
TEST(Cli, CalibrateSuggestsNothingItCannotKnow) {
  const std::string scenario = LUMAVEL_SOURCE_DIR "/host_sim/scenarios/paper_sim_misaligned.yaml";
  LONGS_EQUAL(0, sim("render '" + scenario + "' coarse --resolution 40x30 --duration 4 --quiet").code);
  Outcome r = sim("calibrate coarse --quiet --write coarse.cfg");
  LONGS_EQUAL(1, r.code);
  STRCMP_CONTAINS("misalignment: ", r.out.c_str());  // the estimate is still shown
  STRCMP_CONTAINS("not suggested for a board: the uncertainty, ", r.err.c_str());
  STRCMP_CONTAINS("deg, is above 0.1 deg; nothing written", r.err.c_str());
  CHECK(r.out.find("send to a board") == std::string::npos);
  CHECK(!exists(dir.path() + "/coarse.cfg"));
  LONGS_EQUAL(0, sim("render '" + scenario + "' fine --resolution 160x120 --duration 2 --quiet").code);
  r = sim("calibrate fine --quiet");
  LONGS_EQUAL(0, r.code);
  STRCMP_CONTAINS("send to a board: lumavel-read config set misalignment_rad=", r.out.c_str());
}

// The names calibrate --write puts in its file's comments are shown as
// every name is: a line break in one (a recording folder named
// 'fine<LF>width=160') ended the comment, and the file written, exit 0, held
// a line 'width=160 (lumavel-sim calibrate --write)' that config set refuses.
// The summaries of render and calibrate show the names the same way.
TEST(Cli, CalibrateWritesNamesIntoItsCommentsEscaped) {
  const std::string scenario = LUMAVEL_SOURCE_DIR "/host_sim/scenarios/paper_sim_misaligned.yaml";
  const std::string odd = "\"$(printf 'fine\\nwidth=160')\"";
  Outcome r = sim("render '" + scenario + "' " + odd + " --resolution 160x120 --duration 2");
  LONGS_EQUAL(0, r.code);
  STRCMP_CONTAINS("fine\\x0Awidth=160/mav0: ", r.out.c_str());
  r = sim("calibrate " + odd + " --quiet --write \"$(printf 'c\\033.cfg')\"");
  LONGS_EQUAL(0, r.code);
  STRCMP_CONTAINS("wrote c\\x1B.cfg (", r.out.c_str());
  const std::vector<std::string> lines = fixture::read_lines(dir.path() + "/c\x1b.cfg");
  STRCMP_EQUAL("# lumavel device configuration for fine\\x0Awidth=160 (lumavel-sim calibrate --write)",
               lines.at(0).c_str());
  STRCMP_EQUAL("# send with: lumavel-read config set --file c\\x1B.cfg", lines.at(1).c_str());
  CHECK(lines.at(2).rfind("width=", 0) == 0);
}

// run counts a gyro hole and flags its frames; calibrate said nothing of it
// (found by the corrupted-input campaign, tests/corpus/cli_campaign.cpp).
TEST(Cli, CalibrateSaysTheRecordingHasGaps) {
  fixture::Options o;
  o.gyro_hole_from = 1030000000ull;
  o.gyro_hole_to = 1080000000ull;
  rec(o);
  const Outcome cal = sim("calibrate rec --quiet");
  STRCMP_CONTAINS("calibrate: warning: rec: 0 frame gaps (about 0 pairs missing, longest 0.000 s), 1 gyro holes",
                  cal.err.c_str());
  std::filesystem::remove_all(dir.path() + "/rec");
  rec();
  CHECK(sim("calibrate rec --quiet").err.find("gyro holes") == std::string::npos);
}

// Outputs never land on what the run reads (a CSV written over cam0's
// data.csv destroyed the recording), nor two outputs on one file.
TEST(Cli, OutputsIntoTheRecordingAreRefused) {
  rec();
  const std::string before = fixture::read_text(dir.path() + "/rec/mav0/cam0/data.csv");
  Outcome r = sim("run rec --quiet -o rec/mav0/cam0/data.csv");
  LONGS_EQUAL(2, r.code);
  STRCMP_CONTAINS("rec/mav0/cam0/data.csv (-o): that is part of the recording being read", r.err.c_str());
  CHECK(fixture::read_text(dir.path() + "/rec/mav0/cam0/data.csv") == before);
  r = sim("run rec --quiet -o est.csv --plot rec/mav0/imu0/data.csv");
  LONGS_EQUAL(2, r.code);
  STRCMP_CONTAINS("(--plot): that is part of the recording being read", r.err.c_str());
  r = sim("run rec --quiet -o same.svg --plot same.svg");
  LONGS_EQUAL(2, r.code);
  STRCMP_CONTAINS("same.svg: -o and --plot name the same file", r.err.c_str());
  LONGS_EQUAL(0, sim("run rec --quiet -o rec/est.csv").code);  // beside mav0 is fine
  // A symbolic link to nothing is written through: to the -o file's name, not
  // yet written (was: exit 0, 'plot: lnk.svg' said and the plot replaced by
  // the CSV), or into the recording (was: a new file in mav0, exit 0).
  std::filesystem::create_symlink("new.csv", dir.path() + "/lnk.svg");
  r = sim("run rec --quiet -o new.csv --plot lnk.svg");
  LONGS_EQUAL(2, r.code);
  STRCMP_CONTAINS("lnk.svg: -o and --plot name the same file", r.err.c_str());
  CHECK(!exists(dir.path() + "/new.csv"));
  std::filesystem::create_symlink("rec/mav0/new.csv", dir.path() + "/in.csv");
  r = sim("run rec --quiet -o in.csv");
  LONGS_EQUAL(2, r.code);
  STRCMP_CONTAINS("in.csv (-o): that is part of the recording being read", r.err.c_str());
  CHECK(!exists(dir.path() + "/rec/mav0/new.csv"));
}

// Standard output redirected to a file is one of the outputs: 'run rec >
// rec_estimates.svg' (the default plot's name, in the current folder when
// the CSV goes to standard output) streamed the CSV into the file, then the
// plot was renamed over it: the CSV lost, exit 0; '--hid file:' the same;
// '>> rec/mav0/...' appended to the recording (calibrate's report too).
TEST(Cli, StandardOutputThatIsAnotherOutputIsRefused) {
  rec();
  const std::string cd = "cd '" + dir.path() + "' && '" LUMAVEL_SIM_EXE "' ";
  int status = std::system((cd + "run rec --quiet > rec_estimates.svg 2>err.txt").c_str());
  CHECK(WIFEXITED(status));
  LONGS_EQUAL(2, WEXITSTATUS(status));
  STRCMP_CONTAINS("rec_estimates.svg: standard output (the CSV) and the plot name the same file",
                  fixture::read_text(dir.path() + "/err.txt").c_str());
  STRCMP_EQUAL("", fixture::read_text(dir.path() + "/rec_estimates.svg").c_str());
  // (tool() sends standard output to stdout.txt)
  Outcome r = sim("run rec --quiet --hid file:stdout.txt");
  LONGS_EQUAL(2, r.code);
  STRCMP_CONTAINS("stdout.txt: standard output (the CSV) and --hid file: name the same file", r.err.c_str());
  // The plot on standard output, -o naming that file.
  r = sim("run rec --quiet -o stdout.txt --plot -");
  LONGS_EQUAL(2, r.code);
  STRCMP_CONTAINS("stdout.txt: standard output (the plot) and -o name the same file", r.err.c_str());
  // Appended to a file of the recording.
  const std::string imu = dir.path() + "/rec/mav0/imu0/data.csv", before = fixture::read_text(imu);
  status = std::system((cd + "run rec --quiet >> rec/mav0/imu0/data.csv 2>err.txt").c_str());
  LONGS_EQUAL(2, WEXITSTATUS(status));
  STRCMP_CONTAINS("(standard output (the CSV)): that is part of the recording being read",
                  fixture::read_text(dir.path() + "/err.txt").c_str());
  CHECK(fixture::read_text(imu) == before);
  // calibrate's report the same (was: appended to the sensor.yaml it read, exit 0).
  const std::string yaml = dir.path() + "/rec/mav0/cam1/sensor.yaml", intact = fixture::read_text(yaml);
  status = std::system((cd + "calibrate rec --quiet >> rec/mav0/cam1/sensor.yaml 2>err.txt").c_str());
  LONGS_EQUAL(2, WEXITSTATUS(status));
  STRCMP_CONTAINS("rec/mav0/cam1/sensor.yaml (standard output): that is part of the recording being read",
                  fixture::read_text(dir.path() + "/err.txt").c_str());
  CHECK(fixture::read_text(yaml) == intact);
  // ... and onto its --write file (was: the report lost under the
  // configuration, exit 0), refused before the registration.
  status = std::system((cd + "calibrate rec --quiet --write w.cfg > w.cfg 2>err.txt").c_str());
  LONGS_EQUAL(2, WEXITSTATUS(status));
  STRCMP_CONTAINS("w.cfg: standard output (the report) and --write name the same file",
                  fixture::read_text(dir.path() + "/err.txt").c_str());
  STRCMP_EQUAL("", fixture::read_text(dir.path() + "/w.cfg").c_str());
  // A file standard output is, named by no other output, takes the CSV.
  status = std::system((cd + "run rec --quiet > est.csv 2>err.txt").c_str());
  LONGS_EQUAL(0, WEXITSTATUS(status));
  STRCMP_CONTAINS("timestamp_ns,v_xb_mps", fixture::read_text(dir.path() + "/est.csv").c_str());
  CHECK(exists(dir.path() + "/rec_estimates.svg"));
}

// A report file that cannot be written ends the run with the cause (it was
// counted as overruns and reported as sent).
TEST(Cli, AReportFileThatCannotBeWrittenFailsTheRun) {
  rec();
  const Outcome r = sim("run rec --quiet -o est.csv --hid file:/dev/full");
  LONGS_EQUAL(1, r.code);
  STRCMP_CONTAINS("/dev/full: cannot write the report file: No space left on device", r.err.c_str());
}

// An output that cannot be written says why (was: '/dev/full: write error'
// and '/dev/full: cannot write the plot', no reason), and a CSV that cannot
// be written leaves no plot behind (was: the plot moved into place, exit 1).
TEST(Cli, AnOutputThatCannotBeWrittenSaysWhyAndLeavesNothing) {
  rec();
  Outcome r = sim("run rec --quiet -o /dev/full --plot p.svg");
  LONGS_EQUAL(1, r.code);
  STRCMP_CONTAINS("lumavel-sim run: error: /dev/full: write error: No space left on device\n", r.err.c_str());
  CHECK(!exists(dir.path() + "/p.svg"));
  r = sim("run rec --quiet -o est.csv --plot /dev/full");
  LONGS_EQUAL(1, r.code);
  STRCMP_CONTAINS("lumavel-sim run: error: /dev/full: write error: No space left on device\n", r.err.c_str());
  CHECK(!exists(dir.path() + "/est.csv"));
}

// A --hid-config file that is not a stored configuration is refused before
// the run (was: a warning, exit 0, and a set from the host wrote the store
// over the user's file, a rig.cfg given by mistake).
TEST(Cli, AnInvalidHidConfigIsRefused) {
  rec();
  const std::string rig = "width=40\nheight=30\n";
  fixture::write_text(dir.path() + "/rig.cfg", rig);
  Outcome r = sim("run rec --quiet -o est.csv --hid file:run.hidrep --hid-config rig.cfg");
  LONGS_EQUAL(1, r.code);
  // In a file's words, not a report's (was: '(malformed report: the report was malformed)').
  STRCMP_CONTAINS("lumavel-sim run: error: rig.cfg (--hid-config): is not a stored configuration (its 19 bytes do "
                  "not hold one: a stored configuration is the configuration report, its id, version and CRC "
                  "checked, then the lens tables it names): ",
                  r.err.c_str());
  STRCMP_CONTAINS("give a new name, or a file an earlier run saved there", r.err.c_str());
  CHECK(!exists(dir.path() + "/est.csv") && !exists(dir.path() + "/run.hidrep"));
  fixture::write_text(dir.path() + "/big", std::string(100000, 'x'));
  r = sim("run rec --quiet -o est.csv --hid file:run.hidrep --hid-config big");
  LONGS_EQUAL(1, r.code);
  STRCMP_CONTAINS("big (--hid-config): is 100000 bytes, larger than a stored configuration (", r.err.c_str());
  CHECK(fixture::read_text(dir.path() + "/rig.cfg") == rig);
  fixture::write_text(dir.path() + "/empty", "");  // empty: a new store
  LONGS_EQUAL(0, sim("run rec --quiet -o est.csv --hid file:run.hidrep --hid-config empty").code);
}

// calibrate's --write-size is checked as a usage error naming it.
TEST(Cli, CalibrateRefusesAWriteSizeOutsideTheLimits) {
  rec();
  const Outcome r = sim("calibrate rec --quiet --write c.cfg --write-size 8x30");
  LONGS_EQUAL(2, r.code);
  STRCMP_CONTAINS("--write-size 8x30: the working size must be 16..40 x 1..30", r.err.c_str());
}

// An empty path (an unset shell variable) is a usage error, not the default
// or standard output.
TEST(Cli, AnEmptyPathIsRefusedNamingTheOption) {
  rec();
  for (const auto& [args, option] : std::vector<std::pair<std::string, std::string>>{
           {"run rec -o ''", "--output"},
           {"run rec --plot ''", "--plot"},
           {"run ''", "REC"},
           {"calibrate rec --write ''", "--write"},
           {"render '' out", "SCENARIO"},
           {"import-slider '' out", "DATA_DIR"},
           {"reproduce --out ''", "--out"},
           {"reproduce --doc ''", "--doc"}}) {
    const Outcome r = sim(args);
    LONGS_EQUAL_TEXT(2, r.code, args.c_str());
    STRCMP_CONTAINS((option + ": needs a path, not an empty one").c_str(), r.err.c_str());
  }
  CHECK(!exists(dir.path() + "/rec_estimates.svg"));
}

// --force deleted the scenario and its photo with the old recording when they
// lay inside it: the scenario silently (exit 0), the photo, then "photo does
// not exist". Now refused, nothing deleted.
TEST(Cli, RenderForceKeepsWhatTheRenderReads) {
  std::filesystem::create_directories(dir.path() + "/out/mav0");
  fixture::write_text(dir.path() + "/out/mav0/photo.pgm", "P5\n2 2\n255\n" + std::string("\x10\x80\x40\xF0", 4));
  const std::string scenario =
      "duration_s: 0.1\ncamera: {resolution: [40, 30], rate_hz: 60}\ntrajectory:\n  segments:\n"
      "    - {type: straight, duration_s: 1, speed: 1}\nscene:\n  planes:\n"
      "    - {from: [-3, 2], to: [5, 2], z: [-1, 1], pattern: {type: photo, file: PHOTO, size_m: [2, 2], tiling: mirror}}\n";
  const auto with_photo = [&scenario](const std::string& file) {
    std::string t = scenario;
    return t.replace(t.find("PHOTO"), 5, file);
  };
  fixture::write_text(dir.path() + "/photo.yaml", with_photo("out/mav0/photo.pgm"));
  Outcome r = sim("render photo.yaml out --force -q");
  LONGS_EQUAL(1, r.code);
  STRCMP_CONTAINS("out/mav0/photo.pgm: lies inside out/mav0, which --force would delete: the render reads it", r.err.c_str());
  CHECK(exists(dir.path() + "/out/mav0/photo.pgm"));
  fixture::write_text(dir.path() + "/out/mav0/s.yaml", with_photo("photo.pgm"));
  r = sim("render out/mav0/s.yaml out --force -q");
  LONGS_EQUAL(1, r.code);
  STRCMP_CONTAINS("out/mav0/s.yaml: lies inside out/mav0, which --force would delete", r.err.c_str());
  CHECK(exists(dir.path() + "/out/mav0/s.yaml"));
}

// A render that fails part way leaves no recording behind (was: the frames
// and the tables written until then, as OUT/mav0, exit 1), and names the file
// and the reason (was: 'out/mav0/imu0/data.csv: write error', without it).
// Files of at most 2 KiB (ulimit -f 2, SIGXFSZ ignored: writes then fail with EFBIG).
TEST(Cli, ARenderThatFailsPartWayLeavesNoRecording) {
  const std::string cmd = "cd '" + dir.path() + "' && sh -c \"trap '' XFSZ; ulimit -f 2; exec '" LUMAVEL_SIM_EXE
                          "' render '" LUMAVEL_SOURCE_DIR "/host_sim/scenarios/paper_sim_aligned.yaml' out "
                          "--resolution 40x30 --duration 0.3 -q\" 2>'" + dir.path() + "/stderr.txt'";
  const int status = std::system(cmd.c_str());
  CHECK(WIFEXITED(status));
  LONGS_EQUAL(1, WEXITSTATUS(status));
  STRCMP_CONTAINS("lumavel-sim render: error: out/mav0/imu0/data.csv: write error: File too large\n",
                  fixture::read_text(dir.path() + "/stderr.txt").c_str());
  CHECK(exists(dir.path() + "/out"));  // OUT itself is kept: only what the render wrote in it goes
  CHECK(!exists(dir.path() + "/out/mav0"));
}

// A scenario that loads but describes a recording run refuses (here no
// baseline) fails the render with run's reason, naming the sensor.yaml, and
// before a frame is rendered (was: the whole render, then 'out/mav0 was
// written, but lumavel-sim run refuses it', the recording left behind).
TEST(Cli, RenderRefusesARecordingThatRunWouldRefuse) {
  std::string s = fixture::read_text(LUMAVEL_SOURCE_DIR "/host_sim/scenarios/paper_sim_aligned.yaml");
  const size_t at = s.find("baseline_m:");
  CHECK(at != std::string::npos);
  s.replace(at, s.find('\n', at) - at, "baseline_m: 0");
  fixture::write_text(dir.path() + "/b0.yaml", s);
  const Outcome r = sim("render b0.yaml out --resolution 40x30 --duration 0.2 -q");
  LONGS_EQUAL(1, r.code);
  STRCMP_CONTAINS("b0.yaml: the recording it describes is one lumavel-sim run refuses (nothing rendered): "
                  "out/mav0/cam0/sensor.yaml: T_BS: cam0 and cam1 are less than 0.1 mm apart along body x (no baseline)",
                  r.err.c_str());
  CHECK(!exists(dir.path() + "/out/mav0"));
}

// The same before the render for the frames and the gyro: a duration that
// ends before the first gyro sample (offset_s 1.3 ms) rendered the frames,
// then refused them, leaving out/mav0 behind; a gyro offset beyond the
// duration likewise; a sensor narrower than the kernels need; a view whose
// pixels come out more than 2:1 out of square.
TEST(Cli, RenderRefusesBeforeRenderingWhatRunWouldRefuse) {
  const std::string scenario = LUMAVEL_SOURCE_DIR "/host_sim/scenarios/paper_sim_aligned.yaml";
  Outcome r = sim("render '" + scenario + "' out --resolution 40x30 --duration 0.001 -q");
  LONGS_EQUAL(1, r.code);
  STRCMP_CONTAINS("paper_sim_aligned.yaml: the recording it describes is one lumavel-sim run refuses (nothing "
                  "rendered): out/mav0/imu0/data.csv:2: no gyro samples",
                  r.err.c_str());
  CHECK(!exists(dir.path() + "/out/mav0"));
  std::string s = fixture::read_text(scenario);
  const size_t at = s.find("  rate_hz: 200");
  CHECK(at != std::string::npos);
  s.insert(at, "  offset_s: 100\n");
  fixture::write_text(dir.path() + "/late.yaml", s);
  r = sim("render late.yaml out --resolution 40x30 -q");
  LONGS_EQUAL(1, r.code);
  STRCMP_CONTAINS("late.yaml: the recording it describes is one lumavel-sim run refuses (nothing rendered): "
                  "out/mav0/imu0/data.csv:2: no gyro samples",
                  r.err.c_str());
  r = sim("render '" + scenario + "' out --resolution 4x3 -q");
  LONGS_EQUAL(1, r.code);
  STRCMP_CONTAINS("out/mav0/cam0/sensor.yaml: resolution: the sensor is 4 columns wide", r.err.c_str());
  r = sim("render '" + scenario + "' out --resolution 16384x1 -q");
  LONGS_EQUAL(1, r.code);
  STRCMP_CONTAINS("(nothing rendered): out/mav0/cam0/sensor.yaml: intrinsics: fu = ", r.err.c_str());
  STRCMP_CONTAINS("fv/fu must be 0.5..2", r.err.c_str());
  CHECK(!exists(dir.path() + "/out/mav0"));
}

// A standard output closed at the start ('run REC >&-'): the CSV, gathered
// in a temporary file to be copied to standard output, took descriptor 1
// itself and was copied into itself, then dropped: exit 0, nothing said. Now
// the write fails as on a full disk.
TEST(Cli, AClosedStandardOutputIsAWriteError) {
  rec();
  const std::string cmd = "cd '" + dir.path() + "' && '" LUMAVEL_SIM_EXE "' run rec -q >&- 2>'" + dir.path() +
                          "/stderr.txt'";
  const int status = std::system(cmd.c_str());
  CHECK(WIFEXITED(status));
  LONGS_EQUAL(1, WEXITSTATUS(status));
  STRCMP_EQUAL("lumavel-sim run: error: standard output: write error: Bad file descriptor\n",
               fixture::read_text(dir.path() + "/stderr.txt").c_str());
}

// A first frame at or after the end: first_frame_s 5 s with a duration of 4
// s (or --duration shorter than it). Was 'out/mav0/cam0/data.csv:2: no
// frames (0 before duration_s, all dropped)', a file never written and drops
// the scenario does not have, neither value said.
TEST(Cli, AFirstFrameAfterTheDurationIsSaidAsSuch) {
  std::string s = fixture::read_text(LUMAVEL_SOURCE_DIR "/host_sim/scenarios/paper_sim_aligned.yaml");
  const size_t at = s.find("  rate_hz: 60");
  CHECK(at != std::string::npos);
  s.insert(at, "  first_frame_s: 0.5\n");
  fixture::write_text(dir.path() + "/late_frames.yaml", s);
  const Outcome r = sim("render late_frames.yaml out --resolution 40x30 --duration 0.2 -q");
  LONGS_EQUAL(1, r.code);
  STRCMP_CONTAINS("late_frames.yaml: first_frame_s = 0.5 s is not before duration_s = 0.2 s: frames are rendered at "
                  "first_frame_s + i / rate_hz before duration_s, so the recording would hold none",
                  r.err.c_str());
  CHECK(!exists(dir.path() + "/out/mav0"));
}

// The gyro values run would refuse, before rendering too (was: rendered
// whole, then 'out/mav0 was written, but lumavel-sim run refuses it', exit 1
// and the recording left behind): a 100 m/s turn on a 1 mm radius (a yaw
// rate of 1e5 rad/s), accelerometer noise of 100 m/s^2/sqrt(Hz) at 100 kHz.
TEST(Cli, RenderRefusesBeforeRenderingGyroValuesRunWouldRefuse) {
  std::string s = fixture::read_text(LUMAVEL_SOURCE_DIR "/host_sim/scenarios/paper_sim_aligned.yaml");
  const std::string straight = "{type: straight, duration_s: 8, speed: [0.5, 0.55]}";
  const size_t at = s.find(straight);
  CHECK(at != std::string::npos);
  fixture::write_text(dir.path() + "/spin.yaml",
                      std::string(s).replace(at, straight.size(),
                                             "{type: arc, duration_s: 8, radius_m: 0.001, turn: left, speed: 100}"));
  Outcome r = sim("render spin.yaml out --resolution 40x30 --duration 0.2 -q");
  LONGS_EQUAL(1, r.code);
  STRCMP_CONTAINS("spin.yaml: the recording it describes is one lumavel-sim run refuses (nothing rendered): "
                  "out/mav0/imu0/data.csv:2: column 'w_RS_S_z [rad s^-1]': 100000 is beyond +-1000, more than any "
                  "IMU measures: a corrupt value",
                  r.err.c_str());
  CHECK(!exists(dir.path() + "/out/mav0"));
  const size_t imu = s.find("  rate_hz: 200");
  CHECK(imu != std::string::npos);
  fixture::write_text(dir.path() + "/noisy.yaml",
                      std::string(s).replace(imu, 14, "  rate_hz: 100000\n  accel_noise_density: 100"));
  r = sim("render noisy.yaml out --resolution 40x30 --duration 0.5 -q");
  LONGS_EQUAL(1, r.code);
  STRCMP_CONTAINS("noisy.yaml: the recording it describes is one lumavel-sim run refuses (nothing rendered): "
                  "out/mav0/imu0/data.csv:", r.err.c_str());
  STRCMP_CONTAINS("is beyond +-100000, more than any IMU measures: a corrupt value", r.err.c_str());
  CHECK(!exists(dir.path() + "/out/mav0"));
}

// A scenario's duration_s and render --duration are one rule (was: the file
// took 1e-3..1e6 s, the option (0, 1e6]: --duration 1e-9 was taken).
TEST(Cli, RenderDurationIsTheScenariosRule) {
  const std::string scenario = LUMAVEL_SOURCE_DIR "/host_sim/scenarios/paper_sim_aligned.yaml";
  const Outcome r = sim("render '" + scenario + "' out --resolution 40x30 --duration 1e-9 -q");
  LONGS_EQUAL(2, r.code);
  STRCMP_CONTAINS("--duration: must be a number in [0.001, 1e+06], not '1e-9'", r.err.c_str());
  CHECK(!exists(dir.path() + "/out/mav0"));
}

// cam1's focal lengths 2 % shorter than cam0's (a valid rig): the run went
// on with exit 0 and nothing said, while such a mismatch reads as motion
// (E 12 % on a photo wall where twin cameras give 1 %). Now it warns, even
// with -q; twin cameras are said nothing.
TEST(Cli, RunWarnsOfCamerasWhoseFocalLengthsDiffer) {
  const std::string r = rec();
  Outcome twins = sim("run rec -q -o /dev/null");
  LONGS_EQUAL(0, twins.code);
  STRCMP_EQUAL("", twins.err.c_str());
  const std::string yaml = r + "/mav0/cam1/sensor.yaml";
  std::string text = fixture::read_text(yaml);
  const size_t at = text.find("intrinsics: [");
  const size_t end = text.find(']', at);
  text.replace(at, end - at, "intrinsics: [49, 49, 19.5, 14.5");
  fixture::write_text(yaml, text);
  fixture::write_text(r + "/mav0/cam0/sensor.yaml", [&] {
    std::string t = fixture::read_text(r + "/mav0/cam0/sensor.yaml");
    const size_t a = t.find("intrinsics: [");
    t.replace(a, t.find(']', a) - a, "intrinsics: [50, 50, 19.5, 14.5");
    return t;
  }());
  const Outcome o = sim("run rec -q -o /dev/null");
  LONGS_EQUAL(0, o.code);
  STRCMP_CONTAINS("run: warning: cam1's focal lengths differ from cam0's by 2.0 % (fu 49 / 50 px, fv 49 / 50 px: ",
                  o.err.c_str());
  STRCMP_CONTAINS("rec/mav0/cam1/sensor.yaml:", o.err.c_str());
  STRCMP_CONTAINS("The estimates are not to be trusted\n", o.err.c_str());
}

// One gyro value out and back within a sample (30 rad/s in a quiet gyro: a
// read glitch) is replaced by its neighbours' mean before the engines see
// it, and run says so, even with -q, naming the line (gyro_glitch.hpp).
TEST(Cli, RunSaysAGyroGlitchItRepaired) {
  const std::string r = rec();
  fixture::set_field(r + "/mav0/imu0/data.csv", 40, 3, "30");
  const Outcome o = sim("run rec -q -o /dev/null");
  LONGS_EQUAL(0, o.code);
  STRCMP_CONTAINS("run: warning: 1 gyro value taken as a read glitch and replaced by its neighbours' mean (at "
                  "rec/mav0/imu0/data.csv:40, w_RS_S_z 30 rad/s between ",
                  o.err.c_str());
}

// A frame pair stamped 1 us after the one before it, in both tables (a
// timing glitch: was SATURATED, then FRAME_GAP, the two frames after it ~12 %
// off with no flag) is skipped, the estimator seeing a dropped frame, and run
// says so, even with -q, naming the line, the interval and the rule
// (frame_glitch.hpp).
TEST(Cli, RunSkipsAFrameStampedFarTooCloseToTheOneBefore) {
  const std::string r = rec();
  const fixture::Options opt;
  const Outcome base = sim("run rec -q -o " + dir.path() + "/base.csv");
  LONGS_EQUAL(0, base.code);
  const std::string glitch = std::to_string(fixture::frame_time(opt, 5) + 1000);
  for (const char* cam : {"cam0", "cam1"}) fixture::set_field(r + "/mav0/" + cam + "/data.csv", 8, 0, glitch);
  const Outcome o = sim("run rec -q -o " + dir.path() + "/est.csv");
  LONGS_EQUAL(0, o.code);
  STRCMP_CONTAINS(("run: warning: 1 frame pair skipped as a timing glitch (at rec/mav0/cam0/data.csv:8, t = " +
                   glitch + " ns, 1e-06 s after the previous frame: below 0.5 of the median frame period")
                      .c_str(),
                  o.err.c_str());
  const std::string csv = fixture::read_text(dir.path() + "/est.csv");
  CHECK(csv.find(glitch + ",") == std::string::npos);
  // The frames after it as the untouched recording's, within a few %.
  const std::string before = fixture::read_text(dir.path() + "/base.csv");
  auto v_at = [](const std::string& text, uint64_t t) {
    const size_t at = text.find("\n" + std::to_string(t) + ",");
    CHECK(at != std::string::npos);
    return std::strtod(text.c_str() + text.find(',', at) + 1, nullptr);
  };
  for (int f = 7; f <= 9; ++f) {
    const double want = v_at(before, fixture::frame_time(opt, f)), got = v_at(csv, fixture::frame_time(opt, f));
    CHECK(std::fabs(got - want) <= 0.03 * std::fabs(want) + 1e-3);
  }
}

// cam1 repeating its frame 4 as frame 5 (a new file, the same pixels) while
// cam0 moves on: the pair is skipped as dropped, and run says so, naming the
// file, even with -q (FileStereoCamera::frames_repeated).
TEST(Cli, RunSaysAFrameOneCameraRepeated) {
  const std::string r = rec();
  const fixture::Options o;
  auto frame = [&](int f) { return r + "/mav0/cam1/data/" + std::to_string(fixture::frame_time(o, f)) + ".png"; };
  fixture::write_text(frame(5), fixture::read_text(frame(4)));
  const Outcome out = sim("run rec -q -o " + dir.path() + "/est.csv");
  LONGS_EQUAL(0, out.code);
  STRCMP_CONTAINS(("run: warning: cam1 repeated the frame before on 1 frame pair, the first rec/mav0/cam1/data/" +
                   std::to_string(fixture::frame_time(o, 5)) + ".png")
                      .c_str(),
                  out.err.c_str());
  const std::string csv = fixture::read_text(dir.path() + "/est.csv");
  CHECK(csv.find(std::to_string(fixture::frame_time(o, 5)) + ",") == std::string::npos);
}
