// File-backed HAL drivers: the camera bins with bin_area and keeps order
// across its decode threads; the gyro converts body yaw rate to Q7.24.
#include <cmath>

#include "lumavel/core/binning.hpp"
#include "lumavel/host/file_camera.hpp"
#include "lumavel/host/file_gyro.hpp"
#include "lumavel/host/image_io.hpp"
#include "recording_fixture.hpp"
// CppUTest last: its leak-detector macros redefine new.
#include "CppUTest/TestHarness.h"

using namespace lumavel::host;
using lumavel::hal::CaptureStatus;

TEST_GROUP(FileCamera) {
  fixture::TempDir dir;
};

TEST(FileCamera, BinsEveryFrameWithBinArea) {
  fixture::Options o;
  o.width = 80;
  o.height = 60;
  const Recording r = load_recording(fixture::write_recording(dir.path() + "/rec", o));
  FileStereoCamera cam(r, 40, 30);
  LONGS_EQUAL(40, cam.width());
  LONGS_EQUAL(30, cam.height());
  std::vector<uint8_t> a(1200), b(1200), want(1200);
  lumavel::hal::StereoImage img{0, {a.data(), b.data()}, 0, 0};
  for (int i = 0; i < o.frames; ++i) {
    CHECK(cam.capture(img) == CaptureStatus::kOk);
    CHECK_EQUAL(fixture::frame_time(o, i), img.t_ns);
    LONGS_EQUAL(40, img.width);
    LONGS_EQUAL(30, img.height);
    for (int c = 0; c < 2; ++c) {
      const std::vector<uint8_t> src = fixture::frame_pixels(o, i, c);
      CHECK(lumavel::bin_area({src.data(), 80, 60, 80}, want.data(), 40, 30));
      CHECK(want == (c == 0 ? a : b));
      // And it is the 2x2 block mean, to within the rounding.
      const uint8_t* got = c == 0 ? a.data() : b.data();
      for (int v = 0; v < 30; ++v)
        for (int u = 0; u < 40; ++u) {
          double mean = 0;
          for (int dv = 0; dv < 2; ++dv)
            for (int du = 0; du < 2; ++du) mean += src[static_cast<size_t>((2 * v + dv) * 80 + 2 * u + du)];
          DOUBLES_EQUAL(mean / 4, got[v * 40 + u], 0.5);
        }
    }
  }
  CHECK(cam.capture(img) == CaptureStatus::kEnd);
  CHECK(cam.capture(img) == CaptureStatus::kEnd);
  LONGS_EQUAL(o.frames, cam.frames_delivered());
}

TEST(FileCamera, KeepsOrderWithTwoThreadsAndATinyQueue) {
  fixture::Options o;
  o.frames = 60;
  const Recording r = load_recording(fixture::write_recording(dir.path() + "/rec", o));
  FileStereoCamera cam(r, 40, 30, 2, 2);
  std::vector<uint8_t> a(1200), b(1200);
  lumavel::hal::StereoImage img{0, {a.data(), b.data()}, 0, 0};
  for (int i = 0; i < o.frames; ++i) {
    CHECK(cam.capture(img) == CaptureStatus::kOk);
    CHECK_EQUAL(fixture::frame_time(o, i), img.t_ns);
    CHECK(a == fixture::frame_pixels(o, i, 0));  // same size: binning is the identity
    CHECK(b == fixture::frame_pixels(o, i, 1));
  }
  CHECK(cam.capture(img) == CaptureStatus::kEnd);
}

TEST(FileCamera, StopsEarlyWithoutHanging) {
  fixture::Options o;
  o.frames = 40;
  const Recording r = load_recording(fixture::write_recording(dir.path() + "/rec", o));
  FileStereoCamera cam(r, 20, 15);
  std::vector<uint8_t> a(300), b(300);
  lumavel::hal::StereoImage img{0, {a.data(), b.data()}, 0, 0};
  CHECK(cam.capture(img) == CaptureStatus::kOk);
  // Destroyed with frames still queued: the destructor must join cleanly.
}

TEST(FileCamera, ErrorIsStickyAndNamesTheFrame) {
  fixture::Options o;
  const Recording r = load_recording(fixture::write_recording(dir.path() + "/rec", o));
  fixture::write_text(r.frames[2].path[0], "garbage");
  FileStereoCamera cam(r, 40, 30);
  std::vector<uint8_t> a(1200), b(1200);
  lumavel::hal::StereoImage img{0, {a.data(), b.data()}, 0, 0};
  CHECK(cam.capture(img) == CaptureStatus::kOk);
  CHECK(cam.capture(img) == CaptureStatus::kOk);
  CHECK(cam.capture(img) == CaptureStatus::kError);
  STRCMP_CONTAINS("frame 2 (t=1020000000 ns, cam0)", cam.error().c_str());
  STRCMP_CONTAINS(r.frames[2].path[0].c_str(), cam.error().c_str());
  CHECK(cam.capture(img) == CaptureStatus::kError);
}

TEST(FileCamera, RefusesAWorkingSizeAboveTheSensor) {
  fixture::Options o;
  const Recording r = load_recording(fixture::write_recording(dir.path() + "/rec", o));
  const std::string e = fixture::error_of([&] { FileStereoCamera cam(r, 41, 30); });
  // run's rule and words, at the resolution's line (was: 'cam0/sensor.yaml:
  // cannot bin 40x30 frames to 41x30', a second wording of the rule).
  STRCMP_CONTAINS("cam0/sensor.yaml:", e.c_str());
  STRCMP_CONTAINS(": cannot bin the 40x30 sensor up to the working resolution 41x30", e.c_str());
}

// One camera repeating its frame (the same pixels again, a new file and
// time, while the other camera moves on: a driver read it twice) would read
// as that camera standing still; the pair is skipped as a dropped one and
// counted. Both cameras repeating is a still scene: delivered; so are a
// stuck camera's repeats after its first.
TEST(FileCamera, AFrameOneCameraRepeatsIsSkipped) {
  fixture::Options o;
  const std::string rec = fixture::write_recording(dir.path() + "/rec", o);
  auto frame_file = [&](const std::string& root, int cam, int f) {
    return root + "/mav0/cam" + std::to_string(cam) + "/data/" + std::to_string(fixture::frame_time(o, f)) + ".png";
  };
  fixture::write_text(frame_file(rec, 1, 5), fixture::read_text(frame_file(rec, 1, 4)));
  const Recording r = load_recording(rec);
  FileStereoCamera cam(r, 40, 30);
  std::vector<uint8_t> a(1200), b(1200);
  lumavel::hal::StereoImage img{0, {a.data(), b.data()}, 0, 0};
  std::vector<uint64_t> seen;
  while (cam.capture(img) == CaptureStatus::kOk) seen.push_back(img.t_ns);
  LONGS_EQUAL(o.frames - 1, seen.size());
  for (uint64_t t : seen) CHECK(t != fixture::frame_time(o, 5));
  LONGS_EQUAL(1, cam.frames_repeated(1));
  LONGS_EQUAL(5, cam.first_repeated(1));
  LONGS_EQUAL(0, cam.frames_repeated(0));

  // A camera stuck on one frame: only the first repeat is skipped, the rest
  // are delivered (motion_direction.hpp's still camera says what they are).
  const std::string stuck = fixture::write_recording(dir.path() + "/stuck", o);
  for (int f = 5; f < 10; ++f) fixture::write_text(frame_file(stuck, 1, f), fixture::read_text(frame_file(stuck, 1, 4)));
  const Recording rk = load_recording(stuck);
  FileStereoCamera frozen(rk, 40, 30);
  size_t got = 0;
  while (frozen.capture(img) == CaptureStatus::kOk) ++got;
  LONGS_EQUAL(o.frames - 1, got);
  LONGS_EQUAL(1, frozen.frames_repeated(1));

  const std::string still = fixture::write_recording(dir.path() + "/still", o);
  for (int c = 0; c < 2; ++c) fixture::write_text(frame_file(still, c, 5), fixture::read_text(frame_file(still, c, 4)));
  const Recording rs = load_recording(still);
  FileStereoCamera both(rs, 40, 30);
  size_t delivered = 0;
  while (both.capture(img) == CaptureStatus::kOk) ++delivered;
  LONGS_EQUAL(o.frames, delivered);
  LONGS_EQUAL(0, both.frames_repeated(0) + both.frames_repeated(1));
}

TEST_GROUP(FileGyro) {};

TEST(FileGyro, RateToQ24RoundsAndSaturates) {
  LONGS_EQUAL(1 << 24, rate_to_q24(1.0));
  LONGS_EQUAL(-(3 << 23), rate_to_q24(-1.5));
  const double lsb = 1.0 / (1 << 24);
  LONGS_EQUAL(1, rate_to_q24(0.5 * lsb));    // half away from zero
  LONGS_EQUAL(-1, rate_to_q24(-0.5 * lsb));
  LONGS_EQUAL(0, rate_to_q24(0.49 * lsb));
  LONGS_EQUAL(2147483647, rate_to_q24(128.0));
  LONGS_EQUAL(2147483647, rate_to_q24(1e9));
  LONGS_EQUAL(-2147483647 - 1, rate_to_q24(-128.0));
  LONGS_EQUAL(-2147483647 - 1, rate_to_q24(-1e9));
  LONGS_EQUAL(2147483640, rate_to_q24(128.0 - 8 * lsb));  // 2^31 - 8
}

TEST(FileGyro, ReadsBodyYawRateInOrder) {
  Recording r;
  // IMU mounted rolled +90 degrees about body x: sensor y is body z.
  r.imu.T_BS = {1, 0, 0, 0, 0, 0, -1, 0, 0, 1, 0, 0, 0, 0, 0, 1};
  ImuSample s;
  s.t_ns = 10;
  s.w[0] = 0.3;
  s.w[1] = 0.25;
  s.w[2] = -7;
  r.imu_samples.push_back(s);
  s.t_ns = 20;
  s.w[1] = -2;
  r.imu_samples.push_back(s);
  DOUBLES_EQUAL(0.25, body_yaw_rate(r.imu, r.imu_samples[0]), 0);
  FileGyro g(r);
  lumavel::hal::GyroSample out{};
  CHECK(g.read(out));
  CHECK_EQUAL(10u, out.t_ns);
  LONGS_EQUAL(1 << 22, out.rate_z);
  CHECK(g.read(out));
  CHECK_EQUAL(20u, out.t_ns);
  LONGS_EQUAL(-(2 << 24), out.rate_z);
  CHECK(!g.read(out));
}
