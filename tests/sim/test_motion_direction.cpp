// The motion-direction check of `run` (motion_direction.hpp): both cameras'
// images move the same way on an intact rig; a mirrored camera's move the
// other way, and is said. Then through the command line.
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "lumavel/host/image_io.hpp"
#include "lumavel/host/motion_direction.hpp"
#include "recording_fixture.hpp"
// CppUTest last: its leak-detector macros redefine new.
#include "CppUTest/TestHarness.h"

using namespace lumavel::host;

namespace {

constexpr int kW = 40, kH = 3;

// A W x H frame of a texture moved `shift` columns towards larger u,
// mirrored left-right, or turned upside down (u and v reversed).
std::vector<uint8_t> frame(double shift, bool mirrored = false, bool upside_down = false) {
  std::vector<uint8_t> px(static_cast<size_t>(kW * kH));
  for (int v = 0; v < kH; ++v)
    for (int u = 0; u < kW; ++u) {
      const int su = mirrored || upside_down ? kW - 1 - u : u, sv = upside_down ? kH - 1 - v : v;
      const double x = su - shift;
      px[static_cast<size_t>(v * kW + u)] =
          static_cast<uint8_t>(std::lround(120 + 60 * std::sin(0.7 * x) + 30 * std::sin(1.9 * x + 0.5) + sv));
    }
  return px;
}

// Writes frame i of camera c of the fixture recording: `row` (kW values)
// repeated down the image, or a plain grey image when row is empty.
void write_frame(const std::string& rec, const fixture::Options& o, int c, int i, const std::vector<uint8_t>& row) {
  std::vector<uint8_t> px(static_cast<size_t>(o.width * o.height), 128);
  if (!row.empty())
    for (int v = 0; v < o.height; ++v)
      for (int u = 0; u < o.width; ++u) px[static_cast<size_t>(v * o.width + u)] = row[static_cast<size_t>(u)];
  write_png_gray(rec + "/mav0/cam" + std::to_string(c) + "/data/" + std::to_string(fixture::frame_time(o, i)) + ".png",
                 px.data(), o.width, o.height);
}

// `lumavel-sim run REC -q`, standard error to `err`.
std::string quiet_run(const std::string& rec, const std::string& err) {
  return "'" LUMAVEL_SIM_EXE "' run '" + rec + "' -q -o /dev/null --plot /dev/null 2>'" + err + "'";
}

}  // namespace

TEST_GROUP(MotionDirection){};

TEST(MotionDirection, AnIntactRigMovesBothImagesTheSameWay) {
  MotionDirectionCheck c(kW, kH, -1, -1);
  for (int i = 0; i < 30; ++i) c.add(frame(2.0 * i).data(), frame(2.0 * i + 1.5).data());
  LONGS_EQUAL(29, c.same());
  LONGS_EQUAL(0, c.opposite());
  CHECK_FALSE(c.mirrored());
}

TEST(MotionDirection, AMirroredCameraMovesTheOtherWayAndIsSaid) {
  MotionDirectionCheck c(kW, kH, -1, -1);
  for (int i = 0; i < 30; ++i) c.add(frame(2.0 * i).data(), frame(2.0 * i + 1.5, true).data());
  LONGS_EQUAL(0, c.same());
  LONGS_EQUAL(29, c.opposite());
  CHECK(c.mirrored());
}

// Upside down where T_BS says so (u_sign +1): intact. Upside down where it
// says upright: as mirrored.
TEST(MotionDirection, AnUpsideDownCameraIsIntactWhereItsPoseSaysSo) {
  MotionDirectionCheck said(kW, kH, -1, +1), unsaid(kW, kH, -1, -1);
  for (int i = 0; i < 30; ++i) {
    said.add(frame(2.0 * i).data(), frame(2.0 * i + 1.5, false, true).data());
    unsaid.add(frame(2.0 * i).data(), frame(2.0 * i + 1.5, false, true).data());
  }
  LONGS_EQUAL(29, said.same());
  CHECK_FALSE(said.mirrored());
  CHECK(unsaid.mirrored());
}

// Below a column a frame, standing still, or too few frames: nothing said.
TEST(MotionDirection, SlowMotionOrAFewFramesSayNothing) {
  MotionDirectionCheck slow(kW, kH, -1, -1), still(kW, kH, -1, -1), few(kW, kH, -1, -1);
  for (int i = 0; i < 30; ++i) {
    slow.add(frame(0.3 * i).data(), frame(0.3 * i + 1.5, true).data());
    still.add(frame(0).data(), frame(1.5, true).data());
  }
  for (int i = 0; i < static_cast<int>(kMotionMinOppositeFrames); ++i)  // 19 frame pairs
    few.add(frame(2.0 * i).data(), frame(2.0 * i + 1.5, true).data());
  LONGS_EQUAL(0, slow.same() + slow.opposite());
  LONGS_EQUAL(0, still.same() + still.opposite());
  LONGS_EQUAL(kMotionMinOppositeFrames - 1, few.opposite());
  CHECK_FALSE(slow.mirrored() || still.mirrored() || few.mirrored());
}

// One camera's image stands still while the other's moves: a flat view (a
// covered lens, plain grey) or one frame delivered again and again. Was:
// exit 0, V near 0 against 3.5 m/s (E 99 %) with no fault flag and nothing
// said (the engines' low-texture test sees the other camera's texture).
TEST(MotionDirection, ACameraThatStandsStillWhileTheOtherMovesIsSaid) {
  MotionDirectionCheck intact(kW, kH, -1, -1), flat(kW, kH, -1, -1), frozen(kW, kH, -1, -1), still(kW, kH, -1, -1);
  const std::vector<uint8_t> grey(static_cast<size_t>(kW * kH), 128);
  for (int i = 0; i < 30; ++i) {
    intact.add(frame(2.0 * i).data(), frame(2.0 * i + 1.5).data());
    flat.add(frame(2.0 * i).data(), grey.data());
    frozen.add(frame(1.5).data(), frame(2.0 * i).data());  // cam0 stuck on one frame
    still.add(frame(0).data(), frame(1.5).data());        // the rig standing still
  }
  LONGS_EQUAL(-1, intact.still_camera());
  LONGS_EQUAL(1, flat.still_camera());
  LONGS_EQUAL(29, flat.alone(0));
  LONGS_EQUAL(0, frozen.still_camera());
  LONGS_EQUAL(29, frozen.alone(1));
  LONGS_EQUAL(-1, still.still_camera());
  STRCMP_CONTAINS("cam1's images did not move on 29 of the 29 frames", still_camera_text(1, 29, 29, "R").c_str());
}

// A recording whose cam1 images are mirrored left-right ran with exit 0 and
// E near 100 %, nothing said. The run says it, even with -q; the intact one
// says nothing.
TEST(MotionDirection, RunWarnsOfAMirroredCamera) {
  fixture::TempDir dir;
  fixture::Options o;
  o.frames = 40;
  const std::string rec = fixture::write_recording(dir.path() + "/rec", o);
  auto rewrite = [&](bool mirrored) {
    for (int i = 0; i < o.frames; ++i)
      for (int c = 0; c < 2; ++c) write_frame(rec, o, c, i, frame(2.0 * i + 1.5 * c, c == 1 && mirrored));
  };
  const std::string err = dir.path() + "/stderr.txt";
  const std::string run = quiet_run(rec, err);
  rewrite(false);
  LONGS_EQUAL(0, std::system(run.c_str()));
  STRCMP_EQUAL("", fixture::read_text(err).c_str());
  rewrite(true);
  LONGS_EQUAL(0, std::system(run.c_str()));
  STRCMP_EQUAL(("run: warning: cam0's and cam1's images moved opposite ways on 39 of the 39 frames where both moved a "
                "working column or more. The cameras look the same way (T_BS), so any motion of the rig moves both "
                "images the same way: the images of one camera are mirrored left-right, or upside down where its T_BS "
                "says upright (" + rec + "/mav0/cam0/sensor.yaml, cam1/sensor.yaml). The estimates are not to be "
                "trusted\n").c_str(),
               fixture::read_text(err).c_str());
}

// Through the command line: cam1's frames plain grey, cam0's moving (was:
// exit 0, nothing said).
TEST(MotionDirection, RunWarnsOfACameraThatStandsStill) {
  fixture::TempDir dir;
  fixture::Options o;
  o.frames = 40;
  const std::string rec = fixture::write_recording(dir.path() + "/rec", o);
  for (int i = 0; i < o.frames; ++i)
    for (int c = 0; c < 2; ++c) write_frame(rec, o, c, i, c == 0 ? frame(2.0 * i) : std::vector<uint8_t>{});
  const std::string err = dir.path() + "/stderr.txt";
  LONGS_EQUAL(0, std::system(quiet_run(rec, err).c_str()));
  STRCMP_EQUAL(("run: warning: cam1's images did not move on 39 of the 39 frames where either camera's moved a "
                "working column or more, while cam0's did: the two cameras look the same way (T_BS), so the rig's "
                "motion moves both images. cam1 sees nothing that moves (its lens covered or blocked by something "
                "plain) or delivers the same frame again and again (" + rec + "/mav0/cam1/); V is not observable "
                "from one camera. The estimates are not to be trusted\n").c_str(),
               fixture::read_text(err).c_str());
}
