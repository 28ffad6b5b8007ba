#include <CppUTest/TestHarness.h>

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <vector>

#include "lumavel/core/column_profile.hpp"

using namespace lumavel;

TEST_GROUP(ColumnProfile){};

// Every width's tail, word-aligned rows and not, and the tallest frame
// (each byte lane's largest sum) with bytes near 255 in every lane.
TEST(ColumnProfile, SumsEveryColumnWhateverTheWidth) {
  for (const uint16_t w : std::initializer_list<uint16_t>{16, 17, 18, 19, 40, 159, 160})
    for (const uint16_t h : std::initializer_list<uint16_t>{7, kMaxRows})
      for (const uint16_t pad : std::initializer_list<uint16_t>{3, static_cast<uint16_t>((4 - w % 4) % 4)}) {
        const uint16_t stride = static_cast<uint16_t>(w + pad);
        std::vector<uint8_t> img(static_cast<size_t>(stride) * h, 0xEE);
        for (uint16_t y = 0; y < h; ++y)
          for (uint16_t x = 0; x < w; ++x)
            img[static_cast<size_t>(y * stride + x)] = static_cast<uint8_t>(255 - (x * 13 + y * 31) % 23);
        ColumnProfile p;
        column_profile(img.data(), w, h, stride, nullptr, p);
        for (uint16_t x = 0; x < w; ++x) {
          unsigned s = 0;
          for (uint16_t y = 0; y < h; ++y) s += img[static_cast<size_t>(y * stride + x)];
          LONGS_EQUAL(s, p.sum[x]);
          CHECK_FALSE(p.q8);
        }
      }
}

TEST(ColumnProfile, MaxSizeWhiteFrameDoesNotOverflow) {
  std::vector<uint8_t> img(static_cast<size_t>(kMaxColumns) * kMaxRows, 255);
  ColumnProfile p;
  column_profile(img.data(), kMaxColumns, kMaxRows, kMaxColumns, nullptr, p);
  for (int x = 0; x < kMaxColumns; ++x) LONGS_EQUAL(255 * kMaxRows, p.sum[x]);
  LONGS_EQUAL(p.clip_sampled, p.clipped);  // every sampled pixel is clipped
  // Banded, Q8: the widest band (every row, whole) stays below 2^23.
  ColumnBand band{};
  column_profile(img.data(), kMaxColumns, kMaxRows, kMaxColumns, &band, p);
  CHECK_TRUE(p.q8);
  for (int x = 0; x < kMaxColumns; ++x) LONGS_EQUAL(255 * kMaxRows * 256, p.sum[x]);
}

TEST(ColumnProfile, CountsClippedOnSampledRows) {
  std::vector<uint8_t> img(40 * 9, 100);
  img[0] = 0;        // row 0: sampled
  img[8 * 40] = 255; // row 8: sampled
  img[1 * 40] = 0;   // row 1: not sampled
  ColumnProfile p;
  column_profile(img.data(), 40, 9, 40, nullptr, p);
  LONGS_EQUAL(2, p.clipped);
  LONGS_EQUAL(80, p.clip_sampled);
}

// The clip count's byte lanes against a pixel-by-pixel count: mixed rows of
// 0, 1, 254 and 255 (the neighbours of the clipped values), every width's
// tail, aligned and not, up to the widest row (a lane's largest count).
TEST(ColumnProfile, ClipCountMatchesAPixelByPixelCount) {
  uint32_t seed = 12345;
  const uint8_t values[] = {0, 1, 2, 127, 128, 253, 254, 255};
  for (const uint16_t w : std::initializer_list<uint16_t>{4, 5, 6, 7, 40, 41, 42, 43, kMaxColumns}) {
    for (const uint16_t offset : std::initializer_list<uint16_t>{0, 1}) {
      const uint16_t h = 17, stride = static_cast<uint16_t>(w + offset);
      std::vector<uint8_t> buf(static_cast<size_t>(stride) * h + 4);
      uint8_t* const img = buf.data() + offset;
      for (size_t i = 0; i < static_cast<size_t>(stride) * h; ++i) {
        seed = seed * 1664525u + 1013904223u;
        img[i] = values[seed >> 29];
      }
      unsigned want = 0;
      for (uint16_t y = 0; y < h; y = static_cast<uint16_t>(y + 8))
        for (uint16_t x = 0; x < w; ++x) want += img[y * stride + x] == 0 || img[y * stride + x] == 255;
      ColumnProfile p;
      column_profile(img, w, h, stride, nullptr, p);
      LONGS_EQUAL(want, p.clipped);
      LONGS_EQUAL(3u * w, p.clip_sampled);
    }
  }
}

TEST(ColumnProfile, LineScan) {
  std::vector<uint8_t> img(128);
  for (int i = 0; i < 128; ++i) img[static_cast<size_t>(i)] = static_cast<uint8_t>(i);
  ColumnProfile p;
  column_profile(img.data(), 128, 1, 128, nullptr, p);
  for (int i = 0; i < 128; ++i) LONGS_EQUAL(i, p.sum[i]);
}

// Each column sums its band: whole rows first..h-1-first, the two rows
// outside them at edge/256, the rest not at all; any band, width, stride.
TEST(ColumnProfile, SumsEachColumnsBandWithFractionalEdgeRows) {
  for (const uint16_t w : std::initializer_list<uint16_t>{16, 19, 40, static_cast<uint16_t>(kMaxColumns)}) {
    for (const uint16_t h : std::initializer_list<uint16_t>{2, 7, 30}) {
      const uint16_t stride = static_cast<uint16_t>(w + 1);
      std::vector<uint8_t> img(static_cast<size_t>(stride) * h);
      for (size_t i = 0; i < img.size(); ++i) img[i] = static_cast<uint8_t>((i * 37 + i / 7) % 256);
      ColumnBand band{};
      for (uint16_t x = 0; x < w; ++x) {
        band.first[x] = static_cast<uint8_t>((x * 7 + 3) % ((h + 1) / 2));
        band.edge_q8[x] = static_cast<uint8_t>(band.first[x] == 0 ? 0 : (x * 53) % 256);
      }
      ColumnProfile p;
      column_profile(img.data(), w, h, stride, &band, p);
      for (uint16_t x = 0; x < w; ++x) {
        const unsigned first = band.first[x];
        unsigned s = 0;
        for (unsigned y = first; y + first < h; ++y) s += 256u * img[y * stride + x];
        if (first > 0) s += band.edge_q8[x] * (unsigned{img[(first - 1) * stride + x]} + img[(h - first) * stride + x]);
        LONGS_EQUAL(s, p.sum[x]);
      }
      CHECK_TRUE(p.q8);
    }
  }
}

// With radial rings: the sums are the same bits, sum_y2 is each ring of
// rows' column sums weighed by the ring's mean y^2 (y = (2r + 1 - H) / W,
// Q8), whatever the width, height and stride; the rings cover every row
// once; the white frame of the tallest y stays in range; a band leaves it out.
TEST(ColumnProfile, RadialSumsWeighEachRingOfRowsByItsMeanYSquared) {
  for (const uint16_t w : std::initializer_list<uint16_t>{16, 19, 40, static_cast<uint16_t>(kMaxColumns)}) {
    for (const uint16_t h : std::initializer_list<uint16_t>{2, 3, 5, 7, 30, 31, static_cast<uint16_t>(kMaxRows)}) {
      const uint16_t stride = static_cast<uint16_t>(w + 1);
      std::vector<uint8_t> img(static_cast<size_t>(stride) * h);
      for (size_t i = 0; i < img.size(); ++i) img[i] = static_cast<uint8_t>((i * 37 + i / 7) % 256);
      const RadialRings rings = radial_rings(w, h);
      // Each row's ring: from the nearer edge, against the ring edges.
      std::vector<int> ring(h);
      for (unsigned y = 0; y < h; ++y) {
        const unsigned from_edge = std::min<unsigned>(y, h - 1 - y);
        int k = 0;
        while (k < kRadialRings - 1 && from_edge >= rings.edge[k]) ++k;
        ring[y] = k;
      }
      int64_t rows_y2 = 0;
      for (int k = 0; k < kRadialRings; ++k) {
        double mean = 0;
        unsigned n = 0;
        for (unsigned y = 0; y < h; ++y)
          if (ring[y] == k) {
            mean += std::pow((2.0 * y + 1 - h) / w, 2);
            ++n;
          }
        if (n == 0) continue;
        CHECK(std::fabs(rings.weight_q8[k] - 256 * mean / n) <= 0.5);
        rows_y2 += int64_t{rings.weight_q8[k]} * n;
      }
      LONGS_EQUAL(rows_y2, rings.rows_y2_q8);
      ColumnProfile plain, p;
      RadialSums radial;
      CHECK_FALSE(column_profile(img.data(), w, h, stride, nullptr, plain));
      CHECK_TRUE(column_profile(img.data(), w, h, stride, nullptr, p, &rings, &radial));
      LONGS_EQUAL(rows_y2, radial.rows_y2_q8);
      for (uint16_t x = 0; x < w; ++x) {
        LONGS_EQUAL(plain.sum[x], p.sum[x]);
        int64_t s2 = 0;
        for (unsigned y = 0; y < h; ++y) s2 += int64_t{rings.weight_q8[ring[y]]} * img[y * stride + x];
        LONGS_EQUAL(s2, radial.sum_y2[x]);
      }
    }
  }
  std::vector<uint8_t> white(static_cast<size_t>(kMaxColumns) * kMaxRows, 255);
  const RadialRings tallest = radial_rings(16, kMaxRows);  // H / W = 8
  ColumnProfile p;
  RadialSums radial;
  CHECK_TRUE(column_profile(white.data(), 16, kMaxRows, kMaxColumns, nullptr, p, &tallest, &radial));
  CHECK(radial.sum_y2[0] > 0);
  LONGS_EQUAL(int64_t{255} * radial.rows_y2_q8, radial.sum_y2[0]);
  const RadialRings r30 = radial_rings(40, 30);
  ColumnBand band{};
  CHECK_FALSE(column_profile(white.data(), 40, 30, 40, &band, p, &r30, &radial));
  CHECK_FALSE(column_profile(white.data(), 40, 29, 40, nullptr, p, &r30, &radial));  // rings of another height
}
