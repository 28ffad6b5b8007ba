// The rig as the VO reads it from sensor.yaml, and the rigs it refuses.
#include <cmath>
#include <string>

#include "lumavel/host/vo/stereo_rig.hpp"
#include "lumavel/host/vo_engine.hpp"
#include "recording_fixture.hpp"
// CppUTest last: its leak-detector macros redefine new.
#include "CppUTest/TestHarness.h"

using namespace lumavel::host;

namespace {

// Two left-looking cameras of the recording fixture, cam0 at x0, cam1 at x1.
Recording rig_recording(double x0, double x1, int w = 160, int h = 120) {
  Recording r;
  r.root = "/data/rec/mav0";
  r.cam[0] = fixture::left_camera(w, h, x0);
  r.cam[1] = fixture::left_camera(w, h, x1);
  r.frame_period_s = 0.01;
  return r;
}

std::string refusal(const Recording& r, int w = 40, int h = 30) {
  return fixture::error_of([&] { vo::make_stereo_rig(r, w, h); });
}

}  // namespace

TEST_GROUP(VoRig){};

TEST(VoRig, ReadsTheGeometryFromSensorYaml) {
  const Recording rec = rig_recording(-0.04, 0.04);
  const vo::StereoRig rig = vo::make_stereo_rig(rec, 40, 30);
  // 160x120 binned to 40x30: fu scales by 1/4, the centre keeps the
  // pixel-centre convention ((c + 0.5) / 4 - 0.5).
  DOUBLES_EQUAL(0.9 * 160 / 4, rig.cam[0].K(0, 0), 1e-12);
  DOUBLES_EQUAL((79.5 + 0.5) / 4 - 0.5, rig.cam[0].K(0, 2), 1e-12);
  DOUBLES_EQUAL((59.5 + 0.5) / 4 - 0.5, rig.cam[0].K(1, 2), 1e-12);
  DOUBLES_EQUAL(0.01, rig.cam[1].distortion[0], 0);
  DOUBLES_EQUAL(0.08, rig.baseline, 1e-12);
  // Both look left with image x along body x: cam1 (ahead by 8 cm) sees
  // cam0's points shifted by -8 cm along its own x.
  DOUBLES_EQUAL(-0.08, rig.t_10[0], 1e-12);
  DOUBLES_EQUAL(0, rig.t_10[1], 1e-12);
  DOUBLES_EQUAL(0, rig.t_10[2], 1e-12);
  DOUBLES_EQUAL(1, rig.R_10(0, 0), 1e-12);
  // Lenses read as pinhole on request.
  DOUBLES_EQUAL(0, vo::make_stereo_rig(rec, 40, 30, true).cam[0].distortion[0], 0);
}

TEST(VoRig, RefusesCamerasWithoutBaseline) {
  const std::string e = refusal(rig_recording(0.02, 0.0205));
  STRCMP_CONTAINS("/data/rec/mav0/cam1/sensor.yaml: T_BS: cam1 is 0.0005 m from cam0", e.c_str());
  STRCMP_CONTAINS("stereo needs a baseline of at least 1 mm", e.c_str());
}

TEST(VoRig, RefusesViewsThatDoNotOverlap) {
  Recording rec = rig_recording(-0.04, 0.04);
  // cam1 looking right (-y) instead of left: optical axes 180 deg apart.
  rec.cam[1].T_BS = {-1, 0, 0, 0.04, 0, 0, -1, 0, 0, -1, 0, 0, 0, 0, 0, 1};
  const std::string e = refusal(rec);
  STRCMP_CONTAINS("cam1/sensor.yaml: T_BS: the optical axes of cam0 and cam1 are 180.0 deg apart", e.c_str());
  STRCMP_CONTAINS("overlap too little for stereo", e.c_str());
}

TEST(VoRig, RefusesLineScanAndTooSmallImages) {
  STRCMP_CONTAINS("cam0/sensor.yaml: resolution [128, 1]: the VO needs 2-D images of at least 16x12",
                  refusal(rig_recording(-0.04, 0.04, 128, 1), 128, 1).c_str());
  STRCMP_CONTAINS("cam0/sensor.yaml: working size 20x8 is below the VO's minimum 16x12",
                  refusal(rig_recording(-0.04, 0.04), 20, 8).c_str());
  STRCMP_CONTAINS("cam0/sensor.yaml: cannot bin the 160x120 sensor up to the working size 320x240",
                  refusal(rig_recording(-0.04, 0.04), 320, 240).c_str());
}

TEST(VoRig, RefusesAPoseThatIsNotARotation) {
  Recording rec = rig_recording(-0.04, 0.04);
  rec.cam[0].T_BS[0] = 2;  // scaled axis
  STRCMP_CONTAINS("cam0/sensor.yaml: T_BS: the rotation part is not a rotation", refusal(rec).c_str());
}

TEST(VoRig, TheEngineRefusesTheSameWay) {
  const Recording rec = rig_recording(0.02, 0.02);
  STRCMP_CONTAINS("stereo needs a baseline",
                  fixture::error_of([&] { make_vo_engine(rec, 40, 30); }).c_str());
}
