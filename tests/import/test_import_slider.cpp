// import_slider() on a tiny synthetic slider sequence: a texture sliding past
// the camera by one step per frame, so with h = two frame spacings cam1's
// image is exactly cam0's two frames later.
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include "lumavel/host/groundtruth.hpp"
#include "lumavel/host/image_io.hpp"
#include "lumavel/host/import_slider.hpp"
#include "lumavel/host/recording.hpp"
#include "lumavel/host/rig.hpp"
#include "recording_fixture.hpp"
// CppUTest last: its leak-detector macros redefine new.
#include "CppUTest/TestHarness.h"
#include "CppUTest/MemoryLeakWarningPlugin.h"

using namespace lumavel::host;

namespace {

constexpr int kW = 48, kH = 36, kFrames = 10;
constexpr double kSpeed = 0.25, kFramePeriod = 0.04;  // 1 cm per frame
constexpr double kX0 = 0.1;

double frame_time(int i) { return 0.01 + kFramePeriod * i; }

std::vector<uint8_t> frame_pixels(int i) {
  std::vector<uint8_t> px(static_cast<size_t>(kW * kH));
  for (int v = 0; v < kH; ++v)
    for (int u = 0; u < kW; ++u)
      px[static_cast<size_t>(v * kW + u)] =
          static_cast<uint8_t>(std::lround(128 + 90 * std::sin(0.45 * (u + 3 * i)) + 5 * std::cos(0.3 * v)));
  return px;
}

void write_dataset(const std::string& dir, double k3 = 0) {
  std::filesystem::create_directories(dir + "/images");
  std::ofstream images(dir + "/images.txt");
  for (int i = 0; i < kFrames; ++i) {
    char name[64];
    std::snprintf(name, sizeof name, "images/frame_%08d.png", i);
    const std::vector<uint8_t> px = frame_pixels(i);
    write_png_gray(dir + "/" + name, px.data(), kW, kH);
    images << std::fixed << frame_time(i) << " " << name << "\n";
  }
  std::ofstream gt(dir + "/groundtruth.txt");
  gt.precision(12);
  for (int k = 0; k <= 40; ++k) {
    const double t = 0.01 * k;
    gt << t << " " << kX0 + kSpeed * t << " 0.0 0.0 0.0 0.0 0.0 1.0\n";
  }
  std::ofstream(dir + "/calib.txt") << "50 51 23.5 17.5 -0.1 0.05 0.001 -0.002 " << k3 << "\n";
}

}  // namespace

// The recording library keeps function-local statics (csv column lists) that
// CppUTest's per-test leak check would report; leaks are checked by the
// AddressSanitizer build instead.
TEST_GROUP(ImportSlider) {
  void setup() override { MemoryLeakWarningPlugin::saveAndDisableNewDeleteOverloads(); }
  void teardown() override { MemoryLeakWarningPlugin::restoreNewDeleteOverloads(); }
};

TEST(ImportSlider, Cam1IsCam0HFurtherOnAndTheRigMatchesTheContract) {
  fixture::TempDir tmp;
  write_dataset(tmp.path() + "/data");
  const double h = 0.02;  // two frame spacings
  ImportSliderOptions o;
  o.baseline = h;
  const ImportSliderSummary s = import_slider(tmp.path() + "/data", tmp.path() + "/rec", o);
  LONGS_EQUAL(kFrames, s.frames_in);
  LONGS_EQUAL(kFrames - 2, s.pairs);  // the last two frames have no partner 2 cm further on

  const Recording rec = load_recording(tmp.path() + "/rec");
  LONGS_EQUAL(kFrames - 2, rec.frames.size());
  for (size_t i = 0; i < rec.frames.size(); ++i) {
    CHECK_EQUAL(static_cast<uint64_t>(std::llround(frame_time(static_cast<int>(i)) * 1e9)), rec.frames[i].t_ns);
    const GrayImage c0 = read_gray_image(rec.frames[i].path[0]);
    const GrayImage c1 = read_gray_image(rec.frames[i].path[1]);
    CHECK(c0.px == frame_pixels(static_cast<int>(i)));
    CHECK(c1.px == frame_pixels(static_cast<int>(i) + 2));
  }
  // Same intrinsics and distortion (k3 dropped), cam1 h ahead along body x.
  for (int c = 0; c < 2; ++c) {
    DOUBLES_EQUAL(50, rec.cam[c].fu, 1e-12);
    DOUBLES_EQUAL(51, rec.cam[c].fv, 1e-12);
    DOUBLES_EQUAL(23.5, rec.cam[c].cu, 1e-12);
    DOUBLES_EQUAL(17.5, rec.cam[c].cv, 1e-12);
    LONGS_EQUAL(4, rec.cam[c].distortion.size());
    DOUBLES_EQUAL(-0.002, rec.cam[c].distortion[3], 1e-15);
    DOUBLES_EQUAL(1 / kFramePeriod, rec.cam[c].rate_hz, 1e-6);
  }
  const EstimatorSettings set = derive_settings(rec, WorkingSize{24, 18});
  DOUBLES_EQUAL(h, set.baseline, 1e-12);
  // Left-looking, upright: the optical axis is body +y, u runs along body +x.
  DOUBLES_EQUAL(M_PI / 2, set.cam[0].axis_yaw, 1e-12);
  DOUBLES_EQUAL(set.cam[0].axis_yaw, set.cam[1].axis_yaw, 1e-12);
  LONGS_EQUAL(set.cam[0].u_sign, set.cam[1].u_sign);

  // Zero gyro at 100 Hz covering every frame.
  CHECK(rec.imu_samples.front().t_ns <= rec.frames.front().t_ns);
  CHECK(rec.imu_samples.back().t_ns >= rec.frames.back().t_ns);
  DOUBLES_EQUAL(0.01, rec.imu_period_s, 1e-9);
  for (const ImuSample& m : rec.imu_samples) DOUBLES_EQUAL(0, body_yaw_rate(rec.imu, m), 0);

  // Ground truth: the body origin (h/2 ahead of cam0) moving forward at kSpeed.
  LONGS_EQUAL(41, rec.groundtruth.size());
  DOUBLES_EQUAL(kX0 + 0.5 * h, rec.groundtruth[0].p[0], 1e-12);
  std::vector<uint64_t> t;
  for (const FramePairEntry& f : rec.frames) t.push_back(f.t_ns);
  for (double v : true_forward_velocity(rec.groundtruth, t)) DOUBLES_EQUAL(kSpeed, v, 1e-9);
}

TEST(ImportSlider, AFractionalBaselineBlendsTheBracketingFrames) {
  fixture::TempDir tmp;
  write_dataset(tmp.path() + "/data");
  ImportSliderOptions o;
  o.baseline = 0.015;  // halfway between frames i+1 and i+2
  import_slider(tmp.path() + "/data", tmp.path() + "/rec", o);
  const Recording rec = load_recording(tmp.path() + "/rec");
  LONGS_EQUAL(kFrames - 2, rec.frames.size());
  const GrayImage c1 = read_gray_image(rec.frames[3].path[1]);
  const std::vector<uint8_t> a = frame_pixels(4), b = frame_pixels(5);
  for (size_t p = 0; p < a.size(); ++p) CHECK(std::abs(c1.px[p] - 0.5 * (a[p] + b[p])) <= 0.5 + 1e-9);
}

TEST(ImportSlider, BadInputNamesTheFile) {
  fixture::TempDir tmp;
  write_dataset(tmp.path() + "/data");
  std::filesystem::remove(tmp.path() + "/data/calib.txt");
  try {
    import_slider(tmp.path() + "/data", tmp.path() + "/rec");
    FAIL("a missing calib.txt was accepted");
  } catch (const RecordingError& e) {
    CHECK(std::string(e.what()).find("calib.txt") != std::string::npos);
  }
  std::ofstream(tmp.path() + "/data/calib.txt") << "50 51 23.5\n";
  try {
    import_slider(tmp.path() + "/data", tmp.path() + "/rec");
    FAIL("a short calib.txt was accepted");
  } catch (const RecordingError& e) {
    CHECK(std::string(e.what()).find("calib.txt:1") != std::string::npos);
  }
}

// As render's OUT (was: 'afile/mav0/cam0/data: cannot create folder: Not a directory').
TEST(ImportSlider, AFileAsTheRecordingFolderIsRefused) {
  fixture::TempDir tmp;
  write_dataset(tmp.path() + "/data");
  std::ofstream(tmp.path() + "/afile") << "x\n";
  try {
    import_slider(tmp.path() + "/data", tmp.path() + "/afile");
    FAIL("a file was taken as the recording folder");
  } catch (const RecordingError& e) {
    STRCMP_CONTAINS("afile: is a file, not a folder to write the recording in", e.what());
  }
}

// As render's OUT (was: a folder named '-' made, the recording in it, exit 0).
TEST(ImportSlider, ADashAsTheRecordingFolderIsRefused) {
  fixture::TempDir tmp;
  write_dataset(tmp.path() + "/data");
  char was[4096];
  CHECK(::getcwd(was, sizeof was) != nullptr);
  CHECK(::chdir(tmp.path().c_str()) == 0);  // where a '-' would be made
  std::string e = "(imported)";
  try {
    import_slider("data", "-");
  } catch (const std::exception& x) {
    e = x.what();
  }
  CHECK(::chdir(was) == 0);
  STRCMP_EQUAL("- (OUT_REC): '-' stands for standard output, where no recording is written: give a folder name (./- "
               "for a folder of that name)",
               e.c_str());
  CHECK(!std::filesystem::exists(tmp.path() + "/-"));
}

// A dangling link as OUT_REC, or as OUT_REC/mav0, was taken for nothing there
// (was: 'OUT_REC/mav0/cam0/data: cannot create folder: File exists').
TEST(ImportSlider, ADanglingLinkAsTheRecordingFolderIsSaid) {
  fixture::TempDir tmp;
  write_dataset(tmp.path() + "/data");
  std::filesystem::create_symlink(tmp.path() + "/moved", tmp.path() + "/out");
  ImportSliderOptions o;
  o.baseline = 0.02;
  try {
    import_slider(tmp.path() + "/data", tmp.path() + "/out", o);
    FAIL("a dangling link was taken as the recording folder");
  } catch (const RecordingError& e) {
    STRCMP_CONTAINS(("out: is a symbolic link to " + tmp.path() + "/moved, which does not exist").c_str(), e.what());
  }
  std::filesystem::create_directory(tmp.path() + "/rec");
  std::filesystem::create_symlink(tmp.path() + "/moved", tmp.path() + "/rec/mav0");
  try {
    import_slider(tmp.path() + "/data", tmp.path() + "/rec", o);
    FAIL("a dangling mav0 was taken for none");
  } catch (const RecordingError& e) {
    STRCMP_CONTAINS("rec/mav0: already exists (use --force to replace it)", e.what());
  }
  o.force = true;
  import_slider(tmp.path() + "/data", tmp.path() + "/rec", o);  // the link replaced by the recording
  CHECK(std::filesystem::is_directory(tmp.path() + "/rec/mav0/cam0/data"));
}

// The frames are read as they are written: a damaged late frame left the
// pairs before it as a recording, which 'run' then refused blaming the gyro
// file the import had not written ("imu0/data.csv:2: no gyro samples").
TEST(ImportSlider, AFailedImportLeavesNoRecording) {
  fixture::TempDir tmp;
  const std::string d = tmp.path() + "/data";
  write_dataset(d);
  fixture::write_text(d + "/images/frame_00000008.png", fixture::read_text(d + "/images/frame_00000008.png").substr(0, 70));
  try {
    import_slider(d, tmp.path() + "/rec");
    FAIL("a truncated frame was accepted");
  } catch (const RecordingError& e) {
    STRCMP_CONTAINS((d + "/images.txt:9: ").c_str(), e.what());
  }
  CHECK_FALSE(std::filesystem::exists(tmp.path() + "/rec/mav0"));
}

// A baseline longer than the frames' travel was refused with "baseline
// longer than the travel?", the same words as for a slider that barely moved;
// now the frames' own travel is said.
TEST(ImportSlider, ABaselineLongerThanTheFramesTravelSaysTheTravel) {
  fixture::TempDir tmp;
  const std::string d = tmp.path() + "/data";
  write_dataset(d);
  ImportSliderOptions o;
  o.baseline = 0.5;
  try {
    import_slider(d, tmp.path() + "/rec", o);
    FAIL("a baseline longer than the travel was accepted");
  } catch (const RecordingError& e) {
    STRCMP_EQUAL((d + "/groundtruth.txt: no frame has a partner 0.5 m further on: the frames span 0.09 m of the "
                      "slider's travel (x 0.1025 .. 0.1925 m), and the baseline (--baseline) must be shorter")
                     .c_str(),
                 e.what());
  }
  CHECK_FALSE(std::filesystem::exists(tmp.path() + "/rec/mav0"));
}

// Written over, an earlier recording kept its frames beside the new ones
// (120 old PNGs in cam0/data with 10 new) and was lost without a word.
TEST(ImportSlider, AnExistingRecordingIsRefusedUnlessForced) {
  fixture::TempDir tmp;
  write_dataset(tmp.path() + "/data");
  fixture::write_recording(tmp.path() + "/rec");
  const auto pngs = [&] {
    size_t n = 0;
    for (const auto& e : std::filesystem::directory_iterator(tmp.path() + "/rec/mav0/cam0/data")) n += e.is_regular_file();
    return n;
  };
  const size_t before = pngs();
  try {
    import_slider(tmp.path() + "/data", tmp.path() + "/rec");
    FAIL("an existing recording was written over");
  } catch (const RecordingError& e) {
    STRCMP_CONTAINS("rec/mav0: already exists (use --force to replace it)", e.what());
  }
  LONGS_EQUAL(before, pngs());  // left as it was
  ImportSliderOptions o;
  o.force = true;
  const ImportSliderSummary s = import_slider(tmp.path() + "/data", tmp.path() + "/rec", o);
  LONGS_EQUAL(s.pairs, pngs());  // replaced whole: none of the old frames left
  LONGS_EQUAL(s.pairs, load_recording(tmp.path() + "/rec").frames.size());
  // --force does not delete the dataset it reads (it did, then: 'images.txt:2: ...: does not exist').
  std::filesystem::rename(tmp.path() + "/data", tmp.path() + "/rec/mav0/data");
  try {
    import_slider(tmp.path() + "/rec/mav0/data", tmp.path() + "/rec", o);
    FAIL("the dataset inside OUT_REC/mav0 was taken");
  } catch (const RecordingError& e) {
    STRCMP_CONTAINS("rec/mav0/data: lies inside ", e.what());
    STRCMP_CONTAINS("rec/mav0, which --force would delete before reading it", e.what());
  }
  CHECK(std::filesystem::exists(tmp.path() + "/rec/mav0/data/images.txt"));
}

// What run would refuse of the recording is refused before anything is
// written, by run's own checks (was: imported whole, then 'rec/mav0 was
// written, but lumavel-sim run refuses it', the recording left behind).
TEST(ImportSlider, WhatRunWouldRefuseIsRefusedBeforeWriting) {
  fixture::TempDir tmp;
  const std::string d = tmp.path() + "/data";
  write_dataset(d);
  fixture::write_text(d + "/calib.txt", "1e300 1e300 23.5 17.5 0 0 0 0 0\n");
  try {
    import_slider(d, tmp.path() + "/rec");
    FAIL("a focal length of 1e300 px was imported");
  } catch (const RecordingError& e) {
    STRCMP_CONTAINS((d + ": the recording it makes is one lumavel-sim run refuses (nothing written): " + tmp.path() +
                     "/rec/mav0/cam0/sensor.yaml: intrinsics (at the working resolution): ")
                        .c_str(),
                    e.what());
  }
  CHECK_FALSE(std::filesystem::exists(tmp.path() + "/rec"));
}

TEST(ImportSlider, CommandLineRefusesABadBaseline) {
  const char* argv[] = {"import-slider", "a", "b", "--baseline", "-1"};
  LONGS_EQUAL(2, import_slider_main(5, const_cast<char**>(argv)));
  // Below the recording's 1 mm (was: imported, then refused by run's check).
  const char* argv3[] = {"import-slider", "a", "b", "--baseline", "0.0005"};
  LONGS_EQUAL(2, import_slider_main(5, const_cast<char**>(argv3)));
  const char* argv2[] = {"import-slider", "only-one"};
  LONGS_EQUAL(2, import_slider_main(2, const_cast<char**>(argv2)));
}

// Found by the command-line campaign (tests/corpus/cli_campaign.cpp): each
// was accepted (exit 0, a recording written) or named the wrong thing.
TEST(ImportSlider, DamagedDatasetsAreRefusedNamingTheLine) {
  fixture::TempDir tmp;
  const std::string d = tmp.path() + "/data";
  auto line5 = [&](const std::string& file, const std::function<std::string(const std::string&)>& f) {
    fixture::set_line(d + "/" + file, 5, f(fixture::read_lines(d + "/" + file)[4]));
  };
  const struct {
    std::function<void()> damage;
    std::string refused_with;
  } cases[] = {
      // "0.17abc images/x.png" was read as 0.17 and the file "abc".
      {[&] { line5("images.txt", [](std::string l) { return l.insert(l.find(' '), "abc"); }); },
       "images.txt:5: column 'time': '0.170000abc' is not a number"},
      // -5 s became 18446744068709551616 ns; 1e300 s an int64 overflow.
      // Positions in millimetres (was: imported, exit 0, frames 12 m apart).
      {[&] { line5("groundtruth.txt", [](const std::string& l) { return l.substr(0, l.find(' ')) + " 12.1 0 0 0 0 0 1"; }); },
       "groundtruth.txt:5: x = 12.1 m is 12 m from line 1's 0.1 m: a linear slider's track is at most 10 m "
       "(positions in millimetres? they must be metres)"},
      {[&] { line5("images.txt", [](const std::string& l) { return "-5" + l.substr(l.find(' ')); }); },
       "images.txt:5: time -5 s is outside 0..9.2e9 s"},
      {[&] { line5("groundtruth.txt", [](const std::string& l) { return "1e300" + l.substr(l.find(' ')); }); },
       "groundtruth.txt:5: time 1e+300 s is outside 0..9.2e9 s"},
      // Times 0.1 ns apart became one timestamp twice (was: refused by the
      // writer, naming the recording's cam0/data.csv, not this line).
      {[&] { line5("images.txt", [](const std::string& l) { return "0.1300000001" + l.substr(l.find(' ')); }); },
       "images.txt:5: time 0.1300000001 s is not after line 4's, 0.13 s, to the nanosecond (the recording's "
       "timestamps are whole nanoseconds)"},
      {[&] { line5("groundtruth.txt", [](const std::string& l) { return "0.0300000004" + l.substr(l.find(' ')); }); },
       "groundtruth.txt:5: time 0.0300000004 s is not after line 4's, 0.03 s, to the nanosecond"},
      {[&] { line5("images.txt", [](const std::string& l) { return "0.1" + l.substr(l.find(' ')); }); },
       "images.txt:5: time 0.1 s is not after line 4's, 0.13 s"},
      // Extra fields were ignored.
      {[&] { line5("groundtruth.txt", [](const std::string& l) { return l + " 7"; }); },
       "groundtruth.txt:5: unexpected extra field '7' (expected t x y z qx qy qz qw)"},
      {[&] { fixture::write_text(d + "/calib.txt", "50 51 23.5 17.5 0 0 0 0 0 9\n"); },
       "calib.txt:1: unexpected extra field '9'"},
      // The values unsaid (was: 'focal lengths must be positive' alone).
      {[&] { fixture::write_text(d + "/calib.txt", "50 -51 23.5 17.5 0 0 0 0 0\n"); },
       "calib.txt:1: fx = 50, fy = -51: the focal lengths fx and fy must be positive"},
      {[&] { line5("groundtruth.txt", [](const std::string& l) { return l.substr(0, l.size() - 3) + "0.0"; }); },
       "groundtruth.txt:5: qx qy qz qw is not a unit quaternion (norm 0)"},
      // A camera that turns: the turn was written as none (was: exit 0).
      {[&] { line5("groundtruth.txt", [](const std::string& l) { return l.substr(0, l.rfind(" 0.0 0.0 0.0 1.0")) + " 0.0 0.043619 0.0 0.999048"; }); },
       "groundtruth.txt:5: the camera is turned 5 deg from the dataset's axes (qx qy qz qw = 0 0.043619 0 0.999048): "
       "the import takes the positions as camera axes and makes cam1 from cam0's frames by time shift with a zero gyro, "
       "which holds for a slider that does not turn: at most 1.1458 deg (a pixel at fx = 50 px)"},
      // A slider that moves along y more than x: its positions in another frame
      // than the camera's (was: exit 0, cam1 made by the x shift alone).
      {[&] {
         std::vector<std::string> l = fixture::read_lines(d + "/groundtruth.txt");
         for (std::string& s : l) {
           const size_t a = s.find(' ') + 1, b = s.find(' ', a);
           const double x = std::stod(s.substr(a, b - a));
           s = s.substr(0, b) + " " + std::to_string(2 * (x - kX0)) + s.substr(s.find(' ', b + 1));
         }
         fixture::write_lines(d + "/groundtruth.txt", l);
       },
       "groundtruth.txt: from line 1 to line 41 the slider moves 63.435 deg off the camera's x axis (x 0.1 m, y 0.2 "
       "m, z 0 m): the import makes cam1 from cam0's frames h further on along x, which holds for a slider that moves "
       "along x: at most 1.1458 deg (a pixel at fx = 50 px)"},
      // A slider that ends where it started, or behind (was: 'the slider does
      // not move along +x (the import assumes it does)', no line, no value).
      {[&] {
         std::vector<std::string> l = fixture::read_lines(d + "/groundtruth.txt");
         for (std::string& s : l) {
           const size_t a = s.find(' ') + 1, b = s.find(' ', a);
           s = s.substr(0, a) + std::to_string(3 * kX0 - std::stod(s.substr(a, b - a))) + s.substr(b);
         }
         fixture::write_lines(d + "/groundtruth.txt", l);
       },
       "groundtruth.txt: from line 1 to line 41 the slider moves -0.1 m along x (x 0.2 m to 0.1 m): the import makes "
       "cam1 from cam0's frames h further on along +x, which needs a slider that ends further along +x than it starts"},
      // The recording's physical bounds (was: exit 0, a speed of 2.5e301 m/s written).
      {[&] { line5("groundtruth.txt", [](const std::string& l) { const size_t a = l.find(' ') + 1; return l.substr(0, a) + "1e300" + l.substr(l.find(' ', a)); }); },
       "groundtruth.txt:5: x: 1e+300 m is beyond +-1e+07 m"},
      {[&] { line5("groundtruth.txt", [](const std::string& l) { const size_t a = l.find(' ') + 1; return l.substr(0, a) + "1e5" + l.substr(l.find(' ', a)); }); },
       // (within the recording's bound, beyond a slider's track: refused by
       // the track's rule before its differenced speed is reached)
       "groundtruth.txt:5: x = 100000 m is 99999.9 m from line 1's 0.1 m: a linear slider's track is at most 10 m"},
      // Ground truth on another clock, after every frame (was: 'no frame has a
      // partner 0.020000 m further on (baseline longer than the travel?)').
      {[&] {
         std::vector<std::string> l = fixture::read_lines(d + "/groundtruth.txt");
         for (std::string& s : l) s = "100" + s.substr(1);
         fixture::write_lines(d + "/groundtruth.txt", l);
       },
       "groundtruth.txt: its times (100 .. 100.4 s, lines 1..41) span none of the frames' times in images.txt "
       "(0.01 .. 0.37 s): a frame's position is the ground truth's at its time (another clock or time unit?)"},
      // strtod's hexadecimal form, as the recording tables refuse it (was: 0x32 read as 50).
      {[&] { fixture::write_text(d + "/calib.txt", "0x32 51 23.5 17.5 0 0 0 0 0\n"); },
       "calib.txt:1: column 'fx': '0x32' is a hexadecimal number"},
      // A camera `run` refuses is refused here, naming calib.txt.
      {[&] { fixture::write_text(d + "/calib.txt", "50 51 23.5 1e6 0 0 0 0 0\n"); },
       "calib.txt:1: intrinsics: principal point cv = 1e+06 px"},
      {[&] { fixture::write_text(d + "/calib.txt", "50 51 23.5 17.5 1e10 0 0 0 0\n"); },
       "calib.txt: distortion_coefficients [1e+10, 0, 0, 0]: the lens model cannot be inverted"},
      // Image errors name images.txt's line; a size mismatch gives the sizes.
      {[&] { std::filesystem::remove(d + "/images/frame_00000004.png"); },
       "images.txt:5: " + d + "/images/frame_00000004.png: does not exist"},
      // Its name shown as a field is (was: an escape sequence sent to the terminal).
      {[&] {
         const std::vector<uint8_t> px(40 * kH, 9);
         write_png_gray(d + "/images/f\x1b[2J.png", px.data(), 40, kH);
         line5("images.txt", [](const std::string& l) { return l.substr(0, l.find(' ')) + " images/f\x1b[2J.png"; });
       },
       "images.txt:5: " + d + "/images/f\\x1B[2J.png is 40x36, but " + d + "/images/frame_00000000.png (line 1) is 48x36"},
      {[&] {
         const std::vector<uint8_t> px(40 * kH, 9);
         write_png_gray(d + "/images/frame_00000004.png", px.data(), 40, kH);
       },
       "images.txt:5: " + d + "/images/frame_00000004.png is 40x36, but " + d +
           "/images/frame_00000000.png (line 1) is 48x36: every frame must have the same size"},
  };
  for (const auto& c : cases) {
    std::filesystem::remove_all(d);
    write_dataset(d);
    c.damage();
    std::string e = "(accepted)";
    try {
      ImportSliderOptions o;
      o.baseline = 0.02;
      import_slider(d, tmp.path() + "/rec", o);
    } catch (const RecordingError& x) {
      e = x.what();
    }
    STRCMP_CONTAINS((d + "/" + c.refused_with).c_str(), e.c_str());
  }
}

// An image name with spaces was cut at the first one; a UTF-8 byte order
// mark made line 1 "bad or missing time".
TEST(ImportSlider, NamesWithSpacesAndAByteOrderMarkAreRead) {
  fixture::TempDir tmp;
  const std::string d = tmp.path() + "/data";
  write_dataset(d);
  std::filesystem::rename(d + "/images/frame_00000004.png", d + "/images/frame 4.png");
  std::vector<std::string> l = fixture::read_lines(d + "/images.txt");
  l[4] = l[4].substr(0, l[4].find(' ') + 1) + "images/frame 4.png  ";
  l[0] = "\xEF\xBB\xBF" + l[0];
  fixture::write_lines(d + "/images.txt", l);
  ImportSliderOptions o;
  o.baseline = 0.02;
  const ImportSliderSummary s = import_slider(d, tmp.path() + "/rec", o);
  LONGS_EQUAL(kFrames, s.frames_in);
  LONGS_EQUAL(kFrames - 2, s.pairs);
}
