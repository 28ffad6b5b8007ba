// import_slider() on a tiny synthetic slider sequence: a texture sliding past
// the camera by one step per frame, so with h = two frame spacings cam1's
// image is exactly cam0's two frames later.
#include <cmath>
#include <cstdio>
#include <fstream>
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

TEST(ImportSlider, CommandLineRefusesABadBaseline) {
  const char* argv[] = {"import-slider", "a", "b", "--baseline", "-1"};
  LONGS_EQUAL(2, import_slider_main(5, const_cast<char**>(argv)));
  const char* argv2[] = {"import-slider", "only-one"};
  LONGS_EQUAL(2, import_slider_main(2, const_cast<char**>(argv2)));
}
