// Dropped frame pairs and gyro holes are not errors: they are counted and the
// remaining frames are delivered in order.
#include <tuple>

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

// A gyro that starts late or stops early is not refused: the frames beyond
// it are counted (and flagged GYRO_GAP by the engines); a gyro covering none
// of the frames is refused (it used to give "0 gyro holes" and exit 0).
TEST(Gaps, GyroThatDoesNotCoverTheFrames) {
  fixture::Options o;
  o.frames = 40;  // 1.0 .. 1.39 s at 100 Hz
  const std::string rec = fixture::write_recording(dir.path() + "/rec", o);
  const std::string imu = rec + "/mav0/imu0/data.csv";
  const std::vector<std::string> all = fixture::read_lines(imu);
  auto keep = [&](uint64_t from, uint64_t to, int64_t shift = 0) {
    std::vector<std::string> l = {all[0]};
    for (size_t i = 1; i < all.size(); ++i) {
      const uint64_t t = std::stoull(all[i].substr(0, all[i].find(',')));
      if (t >= from && t <= to) l.push_back(std::to_string(static_cast<int64_t>(t) + shift) + all[i].substr(all[i].find(',')));
    }
    fixture::write_lines(imu, l);
  };
  keep(0, 1200000000ull);  // stops at 1.2 s: frames 1.26 .. 1.39 s beyond (0.05 s tolerated)
  LONGS_EQUAL(14, load_recording(rec).gaps.frames_beyond_gyro);
  keep(1300000000ull, ~0ull);  // starts at 1.3 s
  LONGS_EQUAL(25, load_recording(rec).gaps.frames_beyond_gyro);
  keep(0, ~0ull);
  LONGS_EQUAL(0, load_recording(rec).gaps.frames_beyond_gyro);
  // 1000 s away; ending 0.1 s before the first frame; 5 samples 1 s after the last.
  for (const auto& [from, to, shift] : {std::tuple<uint64_t, uint64_t, int64_t>{0, ~0ull, 1000000000000ll},
                                        {0, ~0ull, -500000000ll}, {1000000000ull, 1008000000ull, 1400000000ll}}) {
    keep(from, to, shift);
    const std::string e = fixture::error_of([&] { load_recording(rec); });
    STRCMP_CONTAINS((imu + ": the gyro samples (t = ").c_str(), e.c_str());
    STRCMP_CONTAINS("cover none of the intervals between the frames of", e.c_str());
    STRCMP_CONTAINS("no heading change can be measured", e.c_str());
  }
}
