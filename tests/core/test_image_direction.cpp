// The images' direction of travel (image_direction.hpp), both engines, on the
// synthetic rig (looking left): the sign of the travel at any depth, none at
// rest under a gyro offset, none for cameras that look along the travel.
#include <CppUTest/TestHarness.h>

#include <cmath>
#include <cstdio>
#include <memory>

#include "lumavel/core/image_direction.hpp"
#include "lumavel/core/kernel_bank.hpp"
#include "lumavel/host/float_image_direction.hpp"
#include "lumavel/host/float_kernel_bank.hpp"
#include "synthetic_rig.hpp"

using namespace lumavel;

namespace {

struct Directions {
  int fixed_known = 0, float_known = 0;  // frames stating a direction (after the first 0.5 s)
  int fixed_wrong = 0, float_wrong = 0;  // ... of the wrong sign
  int split = 0;                         // frames where the two engines differ
};

// 2 s along x at v(t) (frames at 60 Hz), the gyro reading `offset` rad/s
// besides the rig's own turn w (rad/s).
Directions drive(test::SyntheticRig rig, double v, double w, double offset) {
  rig.noise = 1.0;
  const host::EstimatorSettings s = rig.settings();
  auto bank = std::make_unique<KernelBank>();
  build_kernel_bank(host::to_fixed_config(s), *bank);
  const host::FloatKernelBank fbank = host::build_float_kernel_bank(s);
  const int8_t look = image_look(host::to_fixed_config(s).cam[0], host::to_fixed_config(s).cam[1]);
  ImageDirection fixed;
  host::FloatImageDirection dbl;
  StereoMeasurement prev{};
  host::FloatStereoMeasurement fprev;
  Directions d;
  const double dt = 1.0 / 60;
  for (int i = 0; i < 120; ++i) {
    const test::Pose2 p{v * i * dt, 0, w * i * dt};
    ColumnProfile prof[2];
    host::FloatColumnProfile fprof[2];
    for (int c = 0; c < 2; ++c) {
      const auto img = rig.render(c, p);
      column_profile(img.data(), static_cast<uint16_t>(rig.width), static_cast<uint16_t>(rig.height),
                     static_cast<uint16_t>(rig.width), bank->column_band(), prof[c]);
      fprof[c] = host::float_column_profile(fbank.band, img.data(), rig.width, rig.height);
    }
    StereoMeasurement m;
    stereo_measurement(prof[0], prof[1], *bank, nullptr, m);
    const host::FloatStereoMeasurement fm = host::float_stereo_measurement(fprof[0], fprof[1], fbank);
    if (i > 0) {
      const double dtheta = (w + offset) * dt;
      fixed.update(prev, m, static_cast<AngleQ28>(std::llround(std::ldexp(dtheta, 28))), 16666667, look);
      dbl.update(fprev, fm, dtheta, 16666667, host::float_image_look(s.cam[0], s.cam[1]));
      if (i >= 30) {
        d.fixed_known += fixed.direction() != 0;
        d.float_known += dbl.direction() != 0;
        d.fixed_wrong += fixed.direction() * v < 0;
        d.float_wrong += dbl.direction() * v < 0;
        d.split += fixed.direction() != dbl.direction();
      }
    }
    prev = m;
    fprev = fm;
  }
  return d;
}

}  // namespace

TEST_GROUP(ImageDirection){};

// Along +x and -x, past a wall at 0.6 m (the disparity beyond the kernels)
// and at 3 m, while turning at 0.3 rad/s: the direction is the travel's.
TEST(ImageDirection, TheTravelsSignAtAnyDepth) {
  for (const double wall : {0.6, 3.0})
    for (const double v : {0.8, -0.8}) {
      test::SyntheticRig rig;
      rig.wall = wall;
      const Directions d = drive(rig, v, 0.3, 0);
      std::printf("\n  wall at %.1f m, V %+.1f m/s: a direction on %d / %d of 90 frames (fixed / float), %d / %d wrong",
                  wall, v, d.fixed_known, d.float_known, d.fixed_wrong, d.float_wrong);
      CHECK(d.fixed_known > 80);
      LONGS_EQUAL(0, d.fixed_wrong);
      LONGS_EQUAL(0, d.float_wrong);
      LONGS_EQUAL(0, d.split);
    }
}

// At rest, a gyro offset of 5 deg/s unlearned (the images do not turn, the
// gyro says they should have): no direction (kImageDirectionMinRate).
TEST(ImageDirection, NoneAtRestUnderAGyroOffset) {
  test::SyntheticRig rig;
  const Directions d = drive(rig, 0, 0, 5 * M_PI / 180);
  LONGS_EQUAL(0, d.fixed_known);
  LONGS_EQUAL(0, d.float_known);
}

// Cameras looking left or right of the travel state a direction; cameras
// looking along it (within 30 deg) do not.
TEST(ImageDirection, OnlyCamerasThatLookSidewaysStateOne) {
  auto cam = [](double yaw) {
    CameraGeometry g{};
    g.axis_yaw = static_cast<AngleQ28>(std::llround(std::ldexp(yaw, 28)));
    return g;
  };
  auto model = [](double yaw) {
    host::CameraModel c;
    c.axis_yaw = yaw;
    return c;
  };
  const double yaws[] = {M_PI / 2, -M_PI / 2, 0.4, -2.9, M_PI / 2 - 0.9};
  const int want[] = {1, -1, 0, 0, 1};
  for (int i = 0; i < 5; ++i) {
    LONGS_EQUAL(want[i], image_look(cam(yaws[i]), cam(yaws[i])));
    LONGS_EQUAL(want[i], host::float_image_look(model(yaws[i]), model(yaws[i])));
  }
}
