// The common clip ceiling (clip_match.hpp): the darker camera is clamped at
// 255 / g where the brighter one clips, so that the two cameras' binned
// profiles agree after the division by their brightness.
#include <CppUTest/TestHarness.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "lumavel/core/binning.hpp"
#include "lumavel/core/clip_match.hpp"

using namespace lumavel;

namespace {

constexpr int kW = 160, kH = 120;

// A bright, textured scene: radiance in about [20, 250], varying along x
// and, less, along y.
double radiance(int x, int y) {
  return 135 + 80 * std::sin(0.21 * x) * std::cos(0.05 * y) + 35 * std::sin(0.037 * x + 1.0);
}

// A camera: gain, black level, clipped to 8 bits.
std::vector<uint8_t> camera(double gain, double black) {
  std::vector<uint8_t> px(kW * kH);
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      const double v = std::round(gain * radiance(x, y) + black);
      px[static_cast<size_t>(y * kW + x)] = static_cast<uint8_t>(v > 255 ? 255 : (v < 0 ? 0 : v));
    }
  return px;
}

ImageView view(const std::vector<uint8_t>& px) { return {px.data(), kW, kH, kW}; }

// rms over columns of F1 - F0, F = column sum / mean column sum of the 40x30 binned frame.
double profile_difference(const std::vector<uint8_t>& a, const std::vector<uint8_t>& b) {
  std::vector<double> f[2];
  const std::vector<uint8_t>* cams[2] = {&a, &b};
  for (int c = 0; c < 2; ++c) {
    std::vector<uint8_t> out(40 * 30);
    CHECK_TRUE(bin_area(view(*cams[c]), out.data(), 40, 30));
    f[c].assign(40, 0.0);
    double mean = 0;
    for (int y = 0; y < 30; ++y)
      for (int x = 0; x < 40; ++x) f[c][static_cast<size_t>(x)] += out[static_cast<size_t>(y * 40 + x)];
    for (double v : f[c]) mean += v / 40;
    for (double& v : f[c]) v /= mean;
  }
  double ss = 0;
  for (int x = 0; x < 40; ++x) ss += (f[1][static_cast<size_t>(x)] - f[0][static_cast<size_t>(x)]) * (f[1][static_cast<size_t>(x)] - f[0][static_cast<size_t>(x)]);
  return std::sqrt(ss / 40);
}

}  // namespace

TEST_GROUP(ClipMatch){};

TEST(ClipMatch, StatsCountTheSumAndThePixelsAt255) {
  std::vector<uint8_t> px(4 * 3, 10);
  px[5] = 255;
  px[11] = 255;  // outside the 3-wide view below: not counted
  ClipStats s;
  clip_stats({px.data(), 3, 3, 4}, s);
  LONGS_EQUAL(9, s.pixels);
  LONGS_EQUAL(1, s.at_max);
  LONGS_EQUAL(8 * 10 + 255, s.sum);
}

TEST(ClipMatch, TwinsThatDoNotClipAreLeftAlone) {
  const std::vector<uint8_t> a = camera(0.8, 10), b = camera(0.8, 10);
  ClipStats s[2];
  clip_stats(view(a), s[0]);
  clip_stats(view(b), s[1]);
  uint8_t ceiling[2];
  match_clip_ceilings(s[0], s[1], ceiling);
  LONGS_EQUAL(255, ceiling[0]);
  LONGS_EQUAL(255, ceiling[1]);
}

TEST(ClipMatch, ABrighterCameraThatDoesNotClipClampsNothing) {
  const std::vector<uint8_t> a = camera(0.7, 10), b = camera(0.84, 12);  // cam1's brightest about 222
  ClipStats s[2];
  clip_stats(view(a), s[0]);
  clip_stats(view(b), s[1]);
  LONGS_EQUAL(0, s[1].at_max);
  uint8_t ceiling[2];
  match_clip_ceilings(s[0], s[1], ceiling);
  LONGS_EQUAL(255, ceiling[0]);
  LONGS_EQUAL(255, ceiling[1]);
}

// cam1 with 1.2x the gain clips the bright texture that cam0 resolves; with
// cam0 clamped at the ceiling, the normalised profiles agree several times
// better, whichever camera is the brighter one.
TEST(ClipMatch, TheDarkerCameraClippedAlikeMakesTheProfilesAgree) {
  for (int bright = 0; bright < 2; ++bright) {
    std::vector<uint8_t> cam[2];
    cam[bright] = camera(1.2, 12);
    cam[1 - bright] = camera(1.0, 10);
    ClipStats s[2];
    for (int c = 0; c < 2; ++c) clip_stats(view(cam[c]), s[c]);
    CHECK(s[bright].at_max > kW * kH / 50);  // over 2 % clipped
    uint8_t ceiling[2];
    match_clip_ceilings(s[0], s[1], ceiling);
    LONGS_EQUAL(255, ceiling[bright]);
    // 255 / g with g the ratio of the means (about 1.19 here): near 214
    CHECK(ceiling[1 - bright] >= 205 && ceiling[1 - bright] <= 222);
    const double before = profile_difference(cam[0], cam[1]);
    for (int c = 0; c < 2; ++c) clamp_pixels(cam[c].data(), kW, kH, kW, ceiling[c]);
    const double after = profile_difference(cam[0], cam[1]);
    CHECK_TEXT(after < before / 3, ("profile difference " + std::to_string(before) + " -> " + std::to_string(after)).c_str());
  }
}

// Twins whose means differ by what each sees clip on like shares of their
// pixels: no clamp until the brighter one clips on more than
// kClipShareRatio times the darker one's share (shares, not counts: cam1
// has twice the pixels here).
TEST(ClipMatch, LikeSharesAtTheTopAreWhatTheCamerasSeeNotTheirGain) {
  const uint32_t n = 10000;
  const ClipStats s0{uint64_t{100} * n, n, 10};
  uint8_t ceiling[2];
  for (const uint32_t at_max : {0u, 10u, 20u, 40u, 41u, 400u}) {
    const ClipStats s1{uint64_t{110} * 2 * n, 2 * n, at_max};  // 10 % brighter
    match_clip_ceilings(s0, s1, ceiling);
    const bool clamps = at_max * n > kClipShareRatio * 10 * 2 * n;
    LONGS_EQUAL_TEXT(clamps ? 232 : 255, ceiling[0], std::to_string(at_max).c_str());  // 255 / 1.1
    LONGS_EQUAL(255, ceiling[1]);
  }
}

TEST(ClipMatch, ClampRespectsTheStride) {
  std::vector<uint8_t> px = {10, 200, 250, 255, 240, 100, 230, 255};  // 3 pixels + 1 padding, two rows
  clamp_pixels(px.data(), 3, 2, 4, 220);
  const std::vector<uint8_t> want = {10, 200, 220, 255, 220, 100, 220, 255};
  for (size_t i = 0; i < px.size(); ++i) LONGS_EQUAL(want[i], px[i]);
}
