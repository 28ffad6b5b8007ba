// LensRemap: a distorted frame resampled onto the pinhole of its intrinsics.
// No lens is the identity; through a lens each output pixel holds the sensor
// at the distorted position of its own pinhole ray (checked on ramps, where
// bilinear reading is exact up to the 1/256 weights and the final rounding);
// a barrel lens stays inside the sensor, a pincushion lens does not and says so.
#include <cmath>
#include <cstdio>
#include <cstdint>
#include <vector>

#include "lumavel/host/lens_remap.hpp"
// CppUTest last: its leak-detector macros redefine new.
#include "CppUTest/TestHarness.h"

using namespace lumavel::host;

namespace {

constexpr int kW = 160, kH = 120;
constexpr size_t at(int u, int v) { return static_cast<size_t>(v * kW + u); }
const PinholeIntrinsics kIntrinsics{80.0, 80.0, 79.5, 59.5};  // hfov 90 deg, the wide-lens scenes'

LensDistortion lens(double k1, double k2, double p1 = 0, double p2 = 0) {
  LensDistortion l;
  l.k = {k1, k2, p1, p2};
  return l;
}

// Worst |output - expected| over the image, where the input is a ramp along
// one axis (u: value = u * 255 / (W - 1)) and the expectation is that ramp
// at the pixel's distorted position.
double worst_ramp_error(const LensDistortion& l, bool along_u) {
  std::vector<uint8_t> src(kW * kH), dst(kW * kH);
  const double step = 255.0 / ((along_u ? kW : kH) - 1);
  for (int v = 0; v < kH; ++v)
    for (int u = 0; u < kW; ++u) src[at(u, v)] = static_cast<uint8_t>(std::lround((along_u ? u : v) * step));
  const LensRemap remap(kW, kH, kIntrinsics, l);
  remap.apply(src.data(), dst.data());
  double worst = 0;
  for (int v = 0; v < kH; ++v)
    for (int u = 0; u < kW; ++u) {
      double xd = 0, yd = 0;
      l.distort((u - kIntrinsics.cu) / kIntrinsics.fu, (v - kIntrinsics.cv) / kIntrinsics.fv, xd, yd);
      const double s = along_u ? kIntrinsics.fu * xd + kIntrinsics.cu : kIntrinsics.fv * yd + kIntrinsics.cv;
      worst = std::fmax(worst, std::fabs(dst[at(u, v)] - s * step));
    }
  return worst;
}

}  // namespace

TEST_GROUP(LensRemap){};

TEST(LensRemap, NoLensIsTheIdentity) {
  std::vector<uint8_t> src(kW * kH), dst(kW * kH);
  for (size_t i = 0; i < src.size(); ++i) src[i] = static_cast<uint8_t>((i * 37 + i / kW * 11) & 255);
  const LensRemap remap(kW, kH, kIntrinsics, lens(0, 0));
  remap.apply(src.data(), dst.data());
  CHECK(src == dst);
  LONGS_EQUAL(0, remap.outside());
}

// The wide-lens scenes' barrel lens (k1 -0.22, k2 0.05) and a tangential
// one: every output pixel reads its ray's sensor position (a ramp shows the
// position to within the rounding of a 1/256 weight and of the byte: 1 DN).
TEST(LensRemap, EachPixelReadsTheSensorWhereItsRayLands) {
  for (const LensDistortion& l : {lens(-0.22, 0.05), lens(-0.14, 0.02, 0.002, -0.003)}) {
    CHECK(worst_ramp_error(l, true) <= 1.0);
    CHECK(worst_ramp_error(l, false) <= 1.0);
    LONGS_EQUAL(0, LensRemap(kW, kH, kIntrinsics, l).outside());
  }
}

// The same check fails for the identity: the barrel lens moves the border
// pixels by tens of pixels (the ramp's 1.6 DN per pixel), so the test above
// can tell a remap from a copy.
TEST(LensRemap, TheLensMovesTheBorderFarFromACopy) {
  std::vector<uint8_t> src(kW * kH), dst(kW * kH);
  for (int v = 0; v < kH; ++v)
    for (int u = 0; u < kW; ++u) src[at(u, v)] = static_cast<uint8_t>(std::lround(u * 255.0 / (kW - 1)));
  LensRemap(kW, kH, kIntrinsics, lens(-0.22, 0.05)).apply(src.data(), dst.data());
  CHECK(std::abs(int{dst[at(0, 60)]} - int{src[at(0, 60)]}) > 20);
}

// A pincushion lens spreads the periphery: the pinhole's corners look
// outside the sensor; they read the nearest edge pixel and are counted.
TEST(LensRemap, APincushionLensLeavesTheSensorAtTheCorners) {
  const LensRemap remap(kW, kH, kIntrinsics, lens(0.05, 0));
  CHECK(remap.outside() > 0);
  std::vector<uint8_t> src(kW * kH, 100), dst(kW * kH, 0);
  remap.apply(src.data(), dst.data());
  for (uint8_t b : dst) LONGS_EQUAL(100, b);
}

TEST_GROUP(LensInverse){};

// The inverse at every pixel edge of a 4:3 image of 120 deg (normalised
// corners at (+-1.73, +-1.30)) through the wide-lens scenes' barrel (k1 -0.22,
// k2 0.05: one-to-one there). The fixed-point iteration it replaced did not
// settle in those corners, so the renderer refused the lens.
TEST(LensInverse, AStrongBarrelInvertsToItsCornersAtHfov120) {
  LensDistortion lens_model;
  lens_model.k = {-0.22, 0.05, 0, 0};
  const double tx = std::tan(M_PI / 3), ty = tx * 3 / 4;
  double worst = 0, least = 1e9, most = 0;
  for (int j = 0; j <= 30; ++j)
    for (int i = 0; i <= 40; ++i) {
      const double xd = tx * (2.0 * i / 40 - 1), yd = ty * (2.0 * j / 30 - 1);
      double x = 0, y = 0, rx = 0, ry = 0;
      CHECK(lens_model.undistort(xd, yd, x, y));
      lens_model.distort(x, y, rx, ry);
      worst = std::fmax(worst, std::hypot(rx - xd, ry - yd));
      const double scale = lens_radial_scale(xd, yd, x, y);
      least = std::fmin(least, scale);
      most = std::fmax(most, scale);
    }
  std::printf("\n  hfov 120, k1 -0.22, k2 0.05: distort(undistort) off by %.1e at worst; undistorted / distorted "
              "radius %.3f to %.3f", worst, least, most);
  CHECK(worst < 1e-12);
  // Within the plausible range the recording check holds lenses to (rig.cpp).
  CHECK(least >= kLensMinRadialScale && most <= kLensMaxRadialScale);
}

// A lens that folds over (k1 -3: its radius peaks at r = 1/3) has no one-to-one
// inverse beyond the fold: refused there, inverted inside it.
TEST(LensInverse, AFoldingLensIsRefusedBeyondItsFold) {
  LensDistortion lens_model;
  lens_model.k = {-3, 0, 0, 0};
  double x = 0, y = 0;
  CHECK(lens_model.undistort(0.1, 0.05, x, y));
  double rx = 0, ry = 0;
  lens_model.distort(x, y, rx, ry);
  DOUBLES_EQUAL(0.1, rx, 1e-12);
  CHECK_FALSE(lens_model.undistort(0.5, 0.0, x, y));  // the peak radius is 2 / (3 sqrt 3) = 0.385
}
