// Dropped frame pairs and gyro holes are not errors: they are counted and the
// remaining frames are delivered in order.
#include "lumavel/host/file_camera.hpp"
#include "recording_fixture.hpp"
// CppUTest last: its leak-detector macros redefine new.
#include "CppUTest/TestHarness.h"

using namespace lumavel::host;

TEST_GROUP(Gaps) {
  fixture::TempDir dir;
};

TEST(Gaps, DroppedPairsAndGyroHolesAreCountedNotRefused) {
  fixture::Options o;
  o.drop_frames = {3, 4, 8};
  o.gyro_hole_from = 1020000000ull;  // samples 1020..1048 ms missing: 1018 -> 1050 ms
  o.gyro_hole_to = 1050000000ull;
  const Recording r = load_recording(fixture::write_recording(dir.path() + "/rec", o));
  LONGS_EQUAL(9, r.frames.size());
  DOUBLES_EQUAL(0.01, r.frame_period_s, 1e-12);  // median, unaffected by the gaps
  LONGS_EQUAL(2, r.gaps.frame_gaps);
  LONGS_EQUAL(3, r.gaps.frames_missing);
  DOUBLES_EQUAL(0.03, r.gaps.longest_frame_gap_s, 1e-12);
  LONGS_EQUAL(1, r.gaps.gyro_holes);
  DOUBLES_EQUAL(0.032, r.gaps.longest_gyro_hole_s, 1e-12);

  FileStereoCamera cam(r, 40, 30);
  std::vector<uint8_t> a(1200), b(1200);
  lumavel::hal::StereoImage img{0, {a.data(), b.data()}, 0, 0};
  std::vector<uint64_t> seen;
  while (cam.capture(img) == lumavel::hal::CaptureStatus::kOk) {
    seen.push_back(img.t_ns);
  }
  const std::vector<int> kept = {0, 1, 2, 5, 6, 7, 9, 10, 11};
  LONGS_EQUAL(kept.size(), seen.size());
  for (size_t i = 0; i < kept.size(); ++i) CHECK_EQUAL(fixture::frame_time(o, kept[i]), seen[i]);
}

TEST(Gaps, RegularRecordingHasNoGaps) {
  const Recording r = load_recording(fixture::write_recording(dir.path() + "/rec"));
  LONGS_EQUAL(0, r.gaps.frame_gaps);
  LONGS_EQUAL(0, r.gaps.frames_missing);
  LONGS_EQUAL(0, r.gaps.gyro_holes);
}
