// ColumnStream: column sums taken row by row are column_profile()'s, bit for
// bit (sums, edge rows, clipped pixels), with and without a band, at every
// height the estimator takes; rows out of order leave the frame incomplete.
#include <CppUTest/TestHarness.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "lumavel/core/column_stream.hpp"
#include "lumavel/core/estimator.hpp"
#include "left_rig.hpp"

using namespace lumavel;

namespace {

uint32_t next(uint32_t& s) {
  s = s * 1664525u + 1013904223u;
  return s >> 8;
}

std::vector<uint8_t> image(uint16_t w, uint16_t h, uint32_t seed) {
  std::vector<uint8_t> px(static_cast<size_t>(w) * h);
  for (uint8_t& p : px) {
    const uint32_t r = next(seed);
    p = static_cast<uint8_t>(r % 7 == 0 ? (r & 1 ? 255 : 0) : r & 255);  // some clipped pixels
  }
  return px;
}

void check_same(const ColumnProfile& a, const ColumnProfile& b) {
  LONGS_EQUAL(a.width, b.width);
  CHECK_EQUAL(a.q8, b.q8);
  CHECK_EQUAL(a.edges, b.edges);
  LONGS_EQUAL(a.clipped, b.clipped);
  LONGS_EQUAL(a.clip_sampled, b.clip_sampled);
  for (uint16_t u = 0; u < a.width; ++u) LONGS_EQUAL(a.sum[u], b.sum[u]);
  if (a.edges)
    for (uint16_t u = 0; u < a.width; ++u) LONGS_EQUAL(a.edge4[u], b.edge4[u]);
}

}  // namespace

TEST_GROUP(ColumnStream){};

TEST(ColumnStream, RowByRowIsTheWholeFramesProfile) {
  uint32_t seed = 7;
  for (const int wi : {16, 17, 40, 43})
    for (const int hi : {1, 2, 3, 4, 5, 30, 31}) {
      const auto w = static_cast<uint16_t>(wi), h = static_cast<uint16_t>(hi);
      for (const bool banded : {false, true}) {
        ColumnBand band{};
        for (uint16_t u = 0; u < w; ++u) {
          band.first[u] = static_cast<uint8_t>(next(seed) % (h / 2 + 1));
          band.edge_q8[u] = static_cast<uint8_t>(next(seed) & 255);
        }
        const ColumnBand* b = banded && h >= 2 ? &band : nullptr;
        const std::vector<uint8_t> px = image(w, h, next(seed));
        ColumnProfile whole;
        column_profile(px.data(), w, h, w, b, whole);
        ColumnStream s;
        s.start(w, h, b);
        for (uint16_t y = 0; y < h; ++y) {
          CHECK_FALSE(s.complete());
          s.add_row(px.data() + static_cast<size_t>(y) * w, y);
        }
        CHECK(s.complete());
        check_same(whole, s.profile());
      }
    }
}

TEST(ColumnStream, ARowOutOfOrderLeavesTheFrameIncomplete) {
  const std::vector<uint8_t> px = image(40, 30, 3);
  ColumnStream s;
  s.start(40, 30, nullptr);
  for (uint16_t y = 0; y < 30; ++y) s.add_row(px.data() + y * 40, y == 12 ? 13 : y);  // row 12 missing
  CHECK_FALSE(s.complete());
  s.start(40, 30, nullptr);  // a new frame starts clean
  for (uint16_t y = 0; y < 30; ++y) s.add_row(px.data() + y * 40, y);
  CHECK(s.complete());
  s.add_row(px.data(), 0);  // one row too many
  CHECK_FALSE(s.complete());
}

// The estimator stepped from streamed rows (step_profiles) gives what it
// gives from whole frames (step), estimate for estimate.
TEST(ColumnStream, TheEstimatorFromRowsIsTheEstimatorFromFrames) {
  constexpr uint16_t kW = 40, kH = 30;
  // The tests' left-looking rig with the default settings (kernels, options).
  const EstimatorConfig c = host::to_fixed_config(test::left_rig_settings(kW, kH, 50 * M_PI / 180, 0.08, 0));
  static Estimator whole, rows;  // static: a few KB each
  LONGS_EQUAL(static_cast<int>(ConfigError::kOk), static_cast<int>(whole.configure(c)));
  LONGS_EQUAL(static_cast<int>(ConfigError::kOk), static_cast<int>(rows.configure(c)));
  uint32_t seed = 11;
  // A textured scene sliding by a pixel every few frames, with noise.
  std::vector<uint8_t> scene(400);
  for (uint8_t& v : scene) v = static_cast<uint8_t>(60 + next(seed) % 120);
  ColumnStream stream[2];
  uint64_t t = 0;
  int moving = 0;  // frames with a direct measurement: the comparison sees the whole step
  for (int f = 0; f < 60; ++f) {
    t += 16666667;
    for (uint64_t g = t - 16666667 + 2000000; g <= t + 2000000; g += 2000000) {
      const RateQ24 rate = static_cast<RateQ24>((next(seed) % 2001) - 1000);
      whole.push_gyro(g, rate);
      rows.push_gyro(g, rate);
    }
    std::vector<uint8_t> img[2];
    for (int i = 0; i < 2; ++i) {
      img[i].resize(kW * kH);
      for (size_t y = 0; y < kH; ++y)
        for (size_t u = 0; u < kW; ++u)
          img[i][y * kW + u] = static_cast<uint8_t>(
              scene[(u + static_cast<size_t>(f / 3 + 2 * i) + y / 10) % scene.size()] + next(seed) % 5);
    }
    const Estimate a = whole.step({t, {img[0].data(), img[1].data()}, kW});
    for (int i = 0; i < 2; ++i) {
      stream[i].start(kW, kH, rows.bank().column_band());
      for (uint16_t y = 0; y < kH; ++y) stream[i].add_row(img[i].data() + y * kW, y);
      CHECK(stream[i].complete());
    }
    const Estimate b = rows.step_profiles(t, stream[0].profile(), stream[1].profile());
    LONGS_EQUAL(a.v, b.v);
    LONGS_EQUAL(a.status, b.status);
    LONGS_EQUAL(a.heading, b.heading);
    CHECK(a.distance == b.distance);
    LONGS_EQUAL(a.v_direct, b.v_direct);
    moving += a.v_direct != 0;
  }
  CHECK(moving > 30);
}
