// The rotation identity (dF/dtheta from the derivative kernel equals the
// finite difference of F under a rotation of the cameras, paper eq. 6) on
// wide cameras through a barrel lens: the frames undistorted onto their
// pinhole (LensRemap, what `run` does) turn like a pinhole camera's; read as
// pinhole they do not. Sensor 160x120 binned to the product's 40x30, as a
// board or `run` bins it.
#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

#include "lumavel/core/binning.hpp"
#include "lumavel/core/estimator.hpp"
#include "lumavel/host/lens_remap.hpp"
#include "lumavel/host/settings.hpp"
#include "rotation_identity.hpp"
#include "synthetic_rig.hpp"
// CppUTest last: its leak-detector macros redefine new.
#include "CppUTest/TestHarness.h"

using namespace lumavel;

namespace {

constexpr int kSensorW = 160, kSensorH = 120, kWorkW = 40, kWorkH = 30;

enum class Lens { kNone, kUndistorted, kReadAsPinhole };

// One camera's 40x30 working frame at a pose: rendered at the sensor's size
// (through the rig's lens, if any), undistorted or not, binned.
std::vector<uint8_t> working_frame(test::SyntheticRig& rig, int cam, const test::Pose2& p, Lens lens) {
  std::vector<uint8_t> sensor = rig.render(cam, p);
  if (lens == Lens::kUndistorted) {
    std::vector<uint8_t> pinhole(sensor.size());
    host::LensDistortion d;
    d.k = {rig.k1, rig.k2, 0, 0};
    host::LensRemap(kSensorW, kSensorH, {rig.fu(), rig.fv(), (kSensorW - 1) / 2.0, (kSensorH - 1) / 2.0}, d)
        .apply(sensor.data(), pinhole.data());
    sensor.swap(pinhole);
  }
  std::vector<uint8_t> work(static_cast<size_t>(kWorkW * kWorkH));
  const ImageView view{sensor.data(), kSensorW, kSensorH, kSensorW};
  CHECK(bin_area(view, work.data(), kWorkW, kWorkH));
  return work;
}

StereoMeasurement measure_rotated(test::SyntheticRig& rig, const KernelBank& bank, double x, double theta, Lens lens) {
  ColumnProfile prof[2];
  for (int i = 0; i < 2; ++i) {
    const double off = i == 1 ? rig.baseline / 2 : -rig.baseline / 2;
    const test::Pose2 p{x + off - off * std::cos(theta), -off * std::sin(theta), theta};
    const std::vector<uint8_t> img = working_frame(rig, i, p, lens);
    column_profile(img.data(), kWorkW, kWorkH, kWorkW, bank.column_band(), prof[i]);
  }
  StereoMeasurement m;
  stereo_measurement(prof[0], prof[1], bank, nullptr, m);
  return m;
}

double worst_rotation_error(test::SyntheticRig& rig, const KernelBank& bank, Lens lens) {
  return test::worst_rotation_error(bank.count,
                                    [&](double x, double theta) { return measure_rotated(rig, bank, x, theta, lens); });
}

// The wide rig of these tests: 160x120 at hfov (4:3, square pixels), 1.6 deg
// misaligned, the wall's texture as given.
test::SyntheticRig wide_rig(double hfov_deg) {
  test::SyntheticRig rig;
  rig.width = kSensorW;
  rig.height = kSensorH;
  rig.hfov = hfov_deg * M_PI / 180;
  rig.vfov = 2 * std::atan(std::tan(rig.hfov / 2) * 3 / 4);  // square pixels
  rig.supersample = 2;
  rig.misalignment = 1.6 * M_PI / 180;
  return rig;
}

struct IdentityErrors {
  double pinhole, corrected, ignored;  // worst error over rms: no lens, barrel undistorted, barrel read as pinhole
};

// The rig's identity errors without a lens, then through the barrel lens k1 -0.22, k2 0.05.
IdentityErrors identity_errors(test::SyntheticRig rig) {
  const host::EstimatorSettings s = test::left_rig_settings(kWorkW, kWorkH, rig.hfov, rig.baseline, rig.misalignment);
  auto bank = std::make_unique<KernelBank>();
  build_kernel_bank(host::to_fixed_config(s), *bank);
  IdentityErrors e{};
  e.pinhole = worst_rotation_error(rig, *bank, Lens::kNone);
  rig.k1 = -0.22;
  rig.k2 = 0.05;
  e.corrected = worst_rotation_error(rig, *bank, Lens::kUndistorted);
  e.ignored = worst_rotation_error(rig, *bank, Lens::kReadAsPinhole);
  return e;
}

}  // namespace

TEST_GROUP(LensIdentity){};

// hfov 90 and 120 (4:3, square pixels), a barrel lens k1 -0.22, k2 0.05 (the
// wide-lens scenes'; at hfov 120 it still folds nothing). Measured, worst
// error in % of rms (pinhole / lens undistorted / lens read as pinhole):
// hfov 90: 4.40 / 6.62 / 12.27 at 40x30 (4.42 / 5.42 / 6.18 at 80x60,
// 3.76 / 3.11 / 4.81 at 160x120); hfov 120: 240 / 283 / 1037 at 40x30
// (26 / 45 / 97 at 80x60, 19 / 43 / 87 at 160x120). The undistorted lens's
// extra error at 40x30 is the periphery's resolution: a barrel lens gives it
// fewer sensor pixels per pinhole pixel. At hfov 120 the identity fails for
// the pinhole itself: this texture (periods 0.23-0.71 m on a wall 2 m away)
// is squeezed fourfold into the outer columns of a pinhole seen at 60 deg,
// where its 0.23 m period spans 1.6 deg against columns of 1.4: aliased at
// 40x30 (the next test: with its periods doubled the identity holds within
// 5 %; issue 11's 2 % is not met at either field). Bounds: at hfov 90 the undistorted lens within 3
// points of the pinhole and read as pinhole at least 1.5 times as far off;
// at hfov 120 read as pinhole at least twice as far off as undistorted.
TEST(LensIdentity, ABarrelLensUndistortedTurnsLikeAPinhole) {
  for (const double hfov_deg : {90.0, 120.0}) {
    const IdentityErrors e = identity_errors(wide_rig(hfov_deg));
    const double pinhole = e.pinhole, corrected = e.corrected, ignored = e.ignored;
    std::printf("\n  hfov %.0f, 160x120 binned to %dx%d: worst |dF/dtheta - finite difference| = %.2f %% (pinhole), "
                "%.2f %% (barrel lens, undistorted), %.2f %% (barrel lens read as pinhole) of rms\n",
                hfov_deg, kWorkW, kWorkH, 100 * pinhole, 100 * corrected, 100 * ignored);
    if (hfov_deg < 100) {
      CHECK(std::fabs(corrected - pinhole) < 0.03);
      CHECK(ignored > 1.5 * corrected);
    } else {
      CHECK(ignored > 2 * corrected);
    }
  }
}

// The same rig at hfov 120 on a texture the 40x30 columns resolve at the
// periphery (the periods above doubled): the identity holds for the pinhole
// and for the barrel lens undistorted. Measured 4.32 % and 5.70 % of rms (issue
// 11 asks 2 %: missed); bounds 6 % and 8 %. Read as pinhole: 23 %.
TEST(LensIdentity, AtHfov120OnResolvedTextureTheIdentityHolds) {
  test::SyntheticRig rig = wide_rig(120);
  rig.texture = [](double X, double Z) {
    return 128 + 45 * std::sin(2 * M_PI * X / 0.74) * std::cos(2 * M_PI * Z / 1.8) +
           30 * std::sin(2 * M_PI * X / 0.46 + 1.3) + 20 * std::sin(2 * M_PI * X / 1.42 + 0.4);
  };
  const IdentityErrors e = identity_errors(rig);
  const double pinhole = e.pinhole, corrected = e.corrected, ignored = e.ignored;
  std::printf("\n  hfov 120, texture periods doubled, 40x30: worst error %.2f %% (pinhole), %.2f %% (barrel lens, "
              "undistorted), %.2f %% (read as pinhole) of rms\n",
              100 * pinhole, 100 * corrected, 100 * ignored);
  CHECK(pinhole < 0.06);
  CHECK(corrected < 0.08);
  CHECK(ignored > 2 * corrected);
}
