#include <CppUTest/TestHarness.h>

#include <initializer_list>
#include <vector>

#include "lumavel/core/column_profile.hpp"

using namespace lumavel;

TEST_GROUP(ColumnProfile){};

TEST(ColumnProfile, SumsEveryColumnWhateverTheWidth) {
  for (const uint16_t w : std::initializer_list<uint16_t>{16, 17, 18, 19, 40, 159, 160}) {
    const uint16_t h = 7, stride = static_cast<uint16_t>(w + 3);
    std::vector<uint8_t> img(static_cast<size_t>(stride) * h, 0xEE);
    for (uint16_t y = 0; y < h; ++y)
      for (uint16_t x = 0; x < w; ++x) img[static_cast<size_t>(y * stride + x)] = static_cast<uint8_t>((x * 13 + y * 31) % 251);
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
