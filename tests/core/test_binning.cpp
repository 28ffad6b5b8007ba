#include <CppUTest/TestHarness.h>

#include <vector>

#include "lumavel/core/binning.hpp"

using namespace lumavel;

TEST_GROUP(Binning){};

TEST(Binning, IntegerFactorIsBlockMean) {
  std::vector<uint8_t> in(8 * 4);
  for (int i = 0; i < 32; ++i) in[static_cast<size_t>(i)] = static_cast<uint8_t>(i * 7);
  uint8_t out[4 * 2];
  CHECK_TRUE(bin_area({in.data(), 8, 4, 8}, out, 4, 2));
  for (int Y = 0; Y < 2; ++Y)
    for (int X = 0; X < 4; ++X) {
      int s = 0;
      for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 2; ++x) s += in[static_cast<size_t>((2 * Y + y) * 8 + 2 * X + x)];
      LONGS_EQUAL((s + 2) / 4, out[Y * 4 + X]);
    }
}

TEST(Binning, FractionalOverlapWeights) {
  // 3 columns into 2: output 0 = (a + b/2) / 1.5, output 1 = (b/2 + c) / 1.5.
  const uint8_t in[3] = {30, 90, 150};
  uint8_t out[2];
  CHECK_TRUE(bin_area({in, 3, 1, 3}, out, 2, 1));
  LONGS_EQUAL(50, out[0]);   // (30 + 45) / 1.5
  LONGS_EQUAL(130, out[1]);  // (45 + 150) / 1.5
}

TEST(Binning, PreservesUniformAndRespectsStride) {
  std::vector<uint8_t> in(752 * 480, 77);
  for (int y = 0; y < 480; ++y) in[static_cast<size_t>(y * 752 + 751)] = 0;  // padding column, skipped
  std::vector<uint8_t> out(40 * 30);
  CHECK_TRUE(bin_area({in.data(), 751, 480, 752}, out.data(), 40, 30));
  for (uint8_t v : out) LONGS_EQUAL(77, v);
}

TEST(Binning, RefusesImpossibleSizes) {
  uint8_t in[16] = {};
  uint8_t out[64];
  CHECK_FALSE(bin_area({in, 4, 4, 4}, out, 8, 4));   // upsampling
  CHECK_FALSE(bin_area({in, 4, 4, 2}, out, 2, 2));   // stride < width
  CHECK_FALSE(bin_area({nullptr, 4, 4, 4}, out, 2, 2));
  CHECK_FALSE(bin_area({in, 4, 4, 4}, out, 0, 2));
}
