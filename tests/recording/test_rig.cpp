// Rig derivation from T_BS: axis yaw, image orientation, baseline sign and
// misalignment are read from the files, never assumed.
#include <cmath>

#include "lumavel/host/lens_distortion.hpp"
#include "lumavel/host/rig.hpp"
#include "lumavel/host/rig_settings_check.hpp"
#include "recording_fixture.hpp"
// CppUTest last: its leak-detector macros redefine new.
#include "CppUTest/TestHarness.h"

using namespace lumavel::host;
using fixture::error_of;

namespace {

constexpr double kPi = 3.14159265358979323846;

// T_BS with rotation Rz(yaw) * R0 (R0 given by its columns = camera axes in body) at body x.
Pose pose(const double cx[3], const double cy[3], const double cz[3], double x, double yaw = 0) {
  const double c = std::cos(yaw), s = std::sin(yaw);
  auto rz = [&](const double v[3], int row) {
    return row == 0 ? c * v[0] - s * v[1] : row == 1 ? s * v[0] + c * v[1] : v[2];
  };
  Pose p{};
  for (int r = 0; r < 3; ++r) {
    p[static_cast<size_t>(4 * r + 0)] = rz(cx, r);
    p[static_cast<size_t>(4 * r + 1)] = rz(cy, r);
    p[static_cast<size_t>(4 * r + 2)] = rz(cz, r);
  }
  p[3] = x;
  p[15] = 1;
  return p;
}

// Camera axes (x right, y down, z optical) in the body frame.
const double kLeftX[3] = {1, 0, 0}, kLeftY[3] = {0, 0, -1}, kLeftZ[3] = {0, 1, 0};
const double kRightX[3] = {-1, 0, 0}, kRightY[3] = {0, 0, -1}, kRightZ[3] = {0, -1, 0};
const double kFlipX[3] = {-1, 0, 0}, kFlipY[3] = {0, 0, 1}, kFlipZ[3] = {0, 1, 0};  // left, upside down

Recording rig(const Pose& p0, const Pose& p1, int w = 640, int h = 480) {
  Recording r;
  r.root = "/rec/mav0";
  for (int c = 0; c < 2; ++c) {
    r.cam[c] = fixture::left_camera(w, h, 0);
    r.cam[c].fu = 500;
    r.cam[c].cu = 319.5;
  }
  r.cam[0].T_BS = p0;
  r.cam[1].T_BS = p1;
  r.frame_period_s = 0.02;
  return r;
}

}  // namespace

TEST_GROUP(Rig) {};

TEST(Rig, LeftLookingCam1Ahead) {
  const EstimatorSettings s = derive_settings(rig(pose(kLeftX, kLeftY, kLeftZ, -0.04), pose(kLeftX, kLeftY, kLeftZ, 0.04)), {});
  LONGS_EQUAL(40, s.width);
  LONGS_EQUAL(30, s.height);
  DOUBLES_EQUAL(kPi / 2, s.cam[0].axis_yaw, 1e-12);
  DOUBLES_EQUAL(kPi / 2, s.cam[1].axis_yaw, 1e-12);
  LONGS_EQUAL(-1, s.cam[0].u_sign);
  DOUBLES_EQUAL(0.08, s.baseline, 1e-12);
  DOUBLES_EQUAL(0.02, s.frame_period, 0);
  DOUBLES_EQUAL(500.0 / 16, s.cam[0].fu, 1e-12);
  DOUBLES_EQUAL(19.5, s.cam[0].cu, 1e-12);  // the optical centre stays the image centre
}

TEST(Rig, RightLookingCam1Behind) {
  const EstimatorSettings s =
      derive_settings(rig(pose(kRightX, kRightY, kRightZ, 0.05), pose(kRightX, kRightY, kRightZ, -0.03)), {});
  DOUBLES_EQUAL(-kPi / 2, s.cam[0].axis_yaw, 1e-12);
  LONGS_EQUAL(-1, s.cam[0].u_sign);
  LONGS_EQUAL(-1, s.cam[1].u_sign);
  DOUBLES_EQUAL(-0.08, s.baseline, 1e-12);
}

TEST(Rig, UpsideDownCameraFlipsU) {
  const EstimatorSettings s = derive_settings(rig(pose(kFlipX, kFlipY, kFlipZ, 0), pose(kLeftX, kLeftY, kLeftZ, 0.1)), {});
  LONGS_EQUAL(1, s.cam[0].u_sign);
  LONGS_EQUAL(-1, s.cam[1].u_sign);
  DOUBLES_EQUAL(kPi / 2, s.cam[0].axis_yaw, 1e-12);
}

TEST(Rig, MisalignmentIsTheYawBetweenTheCameras) {
  const double d = 1.5 * kPi / 180;
  const EstimatorSettings s =
      derive_settings(rig(pose(kLeftX, kLeftY, kLeftZ, -0.04, 0.3 * d), pose(kLeftX, kLeftY, kLeftZ, 0.04, 1.3 * d)), {});
  DOUBLES_EQUAL(kPi / 2 + 0.3 * d, s.cam[0].axis_yaw, 1e-12);
  DOUBLES_EQUAL(d, s.cam[1].axis_yaw - s.cam[0].axis_yaw, 1e-12);
}

TEST(Rig, IntrinsicsScaleWithPixelCentreConvention) {
  Recording r = rig(pose(kLeftX, kLeftY, kLeftZ, 0), pose(kLeftX, kLeftY, kLeftZ, 0.08));
  r.cam[0].cu = 300;
  const EstimatorSettings s = derive_settings(r, {80, 60});
  DOUBLES_EQUAL(62.5, s.cam[0].fu, 1e-12);
  DOUBLES_EQUAL(300.5 / 8 - 0.5, s.cam[0].cu, 1e-12);
  DOUBLES_EQUAL(39.5, s.cam[1].cu, 1e-12);
  LONGS_EQUAL(80, s.width);
  LONGS_EQUAL(60, s.height);
  const double hfov = 2 * std::atan(320.0 / 500);
  LONGS_EQUAL(default_kernels(hfov).size(), s.kernels.size());
  DOUBLES_EQUAL(default_kernels(hfov)[0].sigma, s.kernels[0].sigma, 0);
}

TEST(Rig, LineScanInputWorksAtHeightOne) {
  const EstimatorSettings s =
      derive_settings(rig(pose(kLeftX, kLeftY, kLeftZ, 0), pose(kLeftX, kLeftY, kLeftZ, 0.08), 128, 1), {64, 30});
  LONGS_EQUAL(64, s.width);
  LONGS_EQUAL(1, s.height);
}

TEST(Rig, BadGeometryOrSizeIsRefused) {
  const Recording ok = rig(pose(kLeftX, kLeftY, kLeftZ, 0), pose(kLeftX, kLeftY, kLeftZ, 0.08));
  STRCMP_CONTAINS("working width 200", error_of([&] { derive_settings(ok, {200, 30}); }).c_str());
  STRCMP_CONTAINS("working width 8", error_of([&] { derive_settings(ok, {8, 30}); }).c_str());
  STRCMP_CONTAINS("working height 129", error_of([&] { derive_settings(ok, {40, 129}); }).c_str());
  const Recording small = rig(pose(kLeftX, kLeftY, kLeftZ, 0), pose(kLeftX, kLeftY, kLeftZ, 0.08), 32, 24);
  const std::string e = error_of([&] { derive_settings(small, {40, 30}); });
  STRCMP_CONTAINS("/rec/mav0/cam0/sensor.yaml: cannot bin the 32x24 sensor up", e.c_str());
  const double up[3] = {0, 0, 1}, fwd[3] = {0, 1, 0};
  const Recording looking_up = rig(pose(kLeftX, fwd, up, 0), pose(kLeftX, kLeftY, kLeftZ, 0.08));
  const std::string up_error = error_of([&] { derive_settings(looking_up, {}); });
  STRCMP_CONTAINS("/rec/mav0/cam0/sensor.yaml: T_BS: this camera looks along body +z: its optical axis is (0, 0, 1) "
                  "in the body frame, more than 60 degrees out of the body x-y plane",
                  up_error.c_str());
  STRCMP_CONTAINS("lumavel needs a rig whose cameras look sideways (optical axis along body +y or -y), with body x "
                  "forward along the travel, y left, z up, and the baseline along x",
                  up_error.c_str());
  const Recording no_baseline = rig(pose(kLeftX, kLeftY, kLeftZ, 0.02), pose(kLeftX, kLeftY, kLeftZ, 0.02));
  STRCMP_CONTAINS("no baseline", error_of([&] { derive_settings(no_baseline, {}); }).c_str());
}

TEST(Rig, FramePeriodComesFromTheTimestamps) {
  fixture::TempDir dir;
  fixture::Options o;
  o.frame_dt = 16666667;  // 60 Hz, while sensor.yaml says rate_hz: 100
  o.drop_frames = {5};
  const EstimatorSettings s = derive_settings(load_recording(fixture::write_recording(dir.path() + "/rec", o)), {});
  DOUBLES_EQUAL(0.016666667, s.frame_period, 1e-12);
  DOUBLES_EQUAL(EstimatorSettings{}.gyro_gap, s.gyro_gap, 0);  // 500 Hz gyro: the default holds
}

TEST(Rig, SlowGyroWidensTheGyroGap) {
  fixture::TempDir dir;
  fixture::Options o;
  o.gyro_dt = 40000000;  // 25 Hz
  const EstimatorSettings s = derive_settings(load_recording(fixture::write_recording(dir.path() + "/rec", o)), {});
  DOUBLES_EQUAL(0.1, s.gyro_gap, 1e-12);
}

// Frames at 1.25 Hz (a period the core takes, up to 1 s): the observer
// bridges intervals of 2.5 periods, not the default 0.5 s, which was shorter
// than one frame interval (was: run refused the recording with "max gap =
// 0.5 s: max gap must be one frame period..4 s"; at 2 Hz with a microsecond of
// jitter every frame restarted the observer).
TEST(Rig, SlowFramesWidenTheMaxGap) {
  fixture::TempDir dir;
  fixture::Options o;
  o.frames = 4;
  o.frame_dt = 800000000;
  const Recording rec = load_recording(fixture::write_recording(dir.path() + "/rec", o));
  const EstimatorSettings s = derive_settings(rec, {});
  DOUBLES_EQUAL(2.0, s.max_gap, 1e-12);
  check_rig_settings(rec, s);  // the core takes it
  fixture::Options fast;  // 100 Hz: the default holds
  DOUBLES_EQUAL(EstimatorSettings{}.max_gap,
                derive_settings(load_recording(fixture::write_recording(dir.path() + "/fast", fast)), {}).max_gap, 0);
}

// A 2 Hz gyro: refused naming its sample interval and the rate it needs (was:
// "imu0/data.csv: the median interval between samples: gyro gap = 1.25 s:
// gyro gap must be 0.1 ms..1 s", a derived setting the recording does not give).
TEST(Rig, TooSlowAGyroIsRefusedNamingItsInterval) {
  fixture::TempDir dir;
  fixture::Options o;
  o.frame_dt = 100000000;
  o.gyro_dt = 500000000;
  const Recording rec = load_recording(fixture::write_recording(dir.path() + "/rec", o));
  const std::string e = error_of([&] { check_rig_settings(rec, derive_settings(rec, {})); });
  STRCMP_CONTAINS("imu0/data.csv: the median interval between samples, 0.5 s (the gyro gap is the larger of 0.05 s "
                  "and 2.5 of them: the gyro must sample every 0.4 s or faster): gyro gap = 1.25 s: gyro gap must be "
                  "0.1 ms..1 s",
                  e.c_str());
}

// A sensor read out through a window off its centre: principal point at
// column 500 of 640. The kernels sized to the whole view reached past the
// right edge and the recording was refused ("a kernel's +-2.5 sigma core
// falls outside a camera's view"); they are sized to the narrower side now.
// A centred camera keeps the kernels of its whole view.
TEST(Rig, KernelsFitAnOffCentrePrincipalPoint) {
  Recording r = rig(pose(kLeftX, kLeftY, kLeftZ, -0.04), pose(kLeftX, kLeftY, kLeftZ, 0.04));
  const EstimatorSettings centred = derive_settings(r, {});
  DOUBLES_EQUAL(std::atan(320.0 / 500) / 4, centred.kernels[0].sigma, 1e-12);
  for (CameraSensor& c : r.cam) c.cu = 500;
  const EstimatorSettings s = derive_settings(r, {});
  check_rig_settings(r, s);  // the core takes it
  DOUBLES_EQUAL(std::atan(139.5 / 500) / 4, s.kernels[0].sigma, 1e-12);
}

TEST(Rig, PinholeCamerasHaveNoEdgeTable) {
  CameraSensor c = fixture::left_camera(640, 480, 0.0);
  c.distortion = {0, 0, 0, 0};
  CHECK_TRUE(undistorted_column_edges(c, 40, M_PI / 2, -1).empty());
}

TEST(Rig, BarrelDistortionWidensTheOuterColumns) {
  // k1 < 0 pulls the image in: undistorting pushes the edges out, the more
  // the further from the centre; the centre column stays where it is.
  CameraSensor c = fixture::left_camera(640, 480, 0.0);
  c.distortion = {-0.14, 0.09, 0, 0};
  const std::vector<double> e = undistorted_column_edges(c, 40, M_PI / 2, -1);
  LONGS_EQUAL(41, static_cast<long>(e.size()));
  const double fu = c.fu;
  auto pinhole = [&](int u) { return M_PI / 2 - std::atan((u * 16.0 - 0.5 - c.cu) / fu); };
  CHECK(e[0] > pinhole(0) + 1e-3);    // left edge further left (yaw up: u_sign -1)
  CHECK(e[40] < pinhole(40) - 1e-3);
  for (int u = 0; u < 40; ++u) CHECK(e[static_cast<size_t>(u + 1)] < e[static_cast<size_t>(u)]);  // monotonic
  // An edge's yaw is the mean over its rows in the common band: beyond the
  // principal row's (rows off it lie further out under a barrel lens), short
  // of the yaw of its top pixel.
  const double xd = (5 * 16.0 - 0.5 - c.cu) / fu;
  auto yaw_at = [&](double yd) {
    LensDistortion lens;
    lens.k = {-0.14, 0.09, 0, 0};
    double x = 0, y = 0;
    CHECK(lens.undistort(xd, yd, x, y));
    return M_PI / 2 - std::atan(x);
  };
  const double principal = yaw_at(0), top = yaw_at((-0.5 - c.cv) / c.fv);
  CHECK(e[5] > principal + 1e-4);
  CHECK(e[5] < top - 1e-4);
}

TEST(Rig, ElevationScalesOfANearPinholeAreTheColumnsCos) {
  // A lens too weak to matter: each column's elevation scale is the
  // pinhole's cos(a_u) (kernel_bank.hpp), a_u the yaw of its centre.
  CameraSensor c = fixture::left_camera(640, 480, 0.0);
  c.distortion = {1e-9, 0, 0, 0};
  const std::vector<double> s = lens_elevation_scales(c, 40);
  LONGS_EQUAL(40, static_cast<long>(s.size()));
  for (int u = 0; u < 40; ++u) {
    const double a = std::atan(((u + 0.5) * 16.0 - 0.5 - c.cu) / c.fu);
    DOUBLES_EQUAL(std::cos(a), s[static_cast<size_t>(u)], 1e-6);
  }
}

TEST(Rig, ElevationScalesOfABarrelLensSetTheBandWhereTheColumnsReachLeast) {
  // Barrel: the edge columns' rows are pulled in hardest, so their band needs
  // the most rows and their scale is the least; the scale of the column that
  // reaches least is 2T f / H exactly, and no column's is below it.
  CameraSensor c = fixture::left_camera(640, 480, 0.0);
  c.distortion = {-0.22, 0.05, 0, 0};
  const std::vector<double> s = lens_elevation_scales(c, 40);
  for (double v : s) CHECK(v > 0 && v < 2);
  CHECK(s[0] < s[20]);
  CHECK(s[39] < s[20]);
  for (size_t u = 0; u + 1 < 20; ++u) CHECK(s[u] <= s[u + 1] + 1e-12);  // rising towards the centre
}

// A sensor narrower than the core's 16 columns is refused naming its
// resolution (it read "working width 10 is outside 16..160", no file, and
// advised a smaller --width).
TEST(Rig, ASensorNarrowerThanSixteenColumnsIsNamed) {
  const Recording narrow = rig(pose(kLeftX, kLeftY, kLeftZ, 0), pose(kLeftX, kLeftY, kLeftZ, 0.08), 10, 8);
  const std::string e = error_of([&] { derive_settings(narrow, {10, 8}); });
  STRCMP_CONTAINS("/rec/mav0/cam0/sensor.yaml", e.c_str());
  STRCMP_CONTAINS("resolution: the sensor is 10 columns wide; lumavel works at 16 columns or more", e.c_str());
}

// Cameras that look different ways push the kernels (centred between the
// axes) out of a view: the error names both T_BS, not cam0's intrinsics.
TEST(Rig, CamerasLookingDifferentWaysNameTheirPoses) {
  const Recording apart = rig(pose(kLeftX, kLeftY, kLeftZ, 0), pose(kLeftX, kLeftY, kLeftZ, 0.08, 0.52));
  const std::string e = error_of([&] { check_rig_settings(apart, derive_settings(apart, {40, 30})); });
  STRCMP_CONTAINS("cam0/sensor.yaml", e.c_str());
  STRCMP_CONTAINS("cam1/sensor.yaml", e.c_str());
  STRCMP_CONTAINS("T_BS: the two cameras' optical axes are 29.8 degrees apart in yaw", e.c_str());
}
