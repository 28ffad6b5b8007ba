// The time-shift pairing of a single slider camera: bracket search, blend
// weights, position interpolation.
#include <cmath>
#include <limits>
#include <vector>

#include "lumavel/host/time_shift_pairing.hpp"
// CppUTest last: its leak-detector macros redefine new.
#include "CppUTest/TestHarness.h"

using namespace lumavel::host;

TEST_GROUP(TimeShiftPairing){};

TEST(TimeShiftPairing, BracketsThePositionHFurtherOnWithPositionWeights) {
  const std::vector<double> x = {0.00, 0.01, 0.02, 0.03, 0.05};
  const std::vector<ShiftedPair> p = plan_time_shift_pairs(x, 0.015);
  LONGS_EQUAL(4, p.size());
  const size_t before[] = {1, 2, 3, 3};
  const double w[] = {0.5, 0.5, 0.25, 0.75};
  for (size_t i = 0; i < 4; ++i) {
    LONGS_EQUAL(i, p[i].cam0);
    LONGS_EQUAL(before[i], p[i].before);
    DOUBLES_EQUAL(w[i], p[i].w, 1e-12);
  }
}

TEST(TimeShiftPairing, StandstillAtTheStartWaitsForTheSliderToMove) {
  const std::vector<double> x = {0.0, 0.0, 0.0, 0.01, 0.02};
  const std::vector<ShiftedPair> p = plan_time_shift_pairs(x, 0.005);
  CHECK(p.size() >= 1);
  LONGS_EQUAL(0, p[0].cam0);
  LONGS_EQUAL(2, p[0].before);
  DOUBLES_EQUAL(0.5, p[0].w, 1e-12);
}

TEST(TimeShiftPairing, NoPartnerPastTheEndOrOnTheRebound) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  // Frame 1's target 0.025 is never reached (0.02 then back to 0.015); frame 4 has no position.
  const std::vector<double> x = {0.0, 0.01, 0.02, 0.015, nan};
  const std::vector<ShiftedPair> p = plan_time_shift_pairs(x, 0.015);
  LONGS_EQUAL(1, p.size());
  LONGS_EQUAL(0, p[0].cam0);
  LONGS_EQUAL(1, p[0].before);
  CHECK(plan_time_shift_pairs({nan, 0.0, 0.1}, 0.05).size() == 1);
}

TEST(TimeShiftPairing, PositionIsInterpolatedInTimeAndUnknownOutside) {
  std::vector<SliderPose> poses(3);
  poses[0].t = 1.0;
  poses[0].p[0] = 0.10;
  poses[1].t = 1.1;
  poses[1].p[0] = 0.12;
  poses[2].t = 1.3;
  poses[2].p[0] = 0.20;
  DOUBLES_EQUAL(0.11, slider_position_at(poses, 1.05), 1e-12);
  DOUBLES_EQUAL(0.16, slider_position_at(poses, 1.2), 1e-12);
  DOUBLES_EQUAL(0.10, slider_position_at(poses, 1.0), 1e-12);
  DOUBLES_EQUAL(0.20, slider_position_at(poses, 1.3), 1e-12);
  CHECK(std::isnan(slider_position_at(poses, 0.99)));
  CHECK(std::isnan(slider_position_at(poses, 1.31)));
}

TEST(TimeShiftPairing, BlendIsPixelwiseAndRounded) {
  const uint8_t a[] = {10, 0, 255, 100};
  const uint8_t b[] = {20, 255, 0, 101};
  uint8_t out[4];
  blend_gray(a, b, 0.25, 4, out);
  LONGS_EQUAL(13, out[0]);   // 12.5 rounds away from zero
  LONGS_EQUAL(64, out[1]);   // 63.75
  LONGS_EQUAL(191, out[2]);  // 191.25
  LONGS_EQUAL(100, out[3]);  // 100.25
  blend_gray(a, b, 1.0, 4, out);
  for (int i = 0; i < 4; ++i) LONGS_EQUAL(b[i], out[i]);
  blend_gray(a, b, 0.0, 4, out);
  for (int i = 0; i < 4; ++i) LONGS_EQUAL(a[i], out[i]);
}
