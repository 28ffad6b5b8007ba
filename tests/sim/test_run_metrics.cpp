// The paper's error E (eq. 22) and the other summary figures.
#include <cmath>

#include "lumavel/host/run_metrics.hpp"
// CppUTest last: its leak-detector macros redefine new.
#include "CppUTest/TestHarness.h"

using namespace lumavel::host;

namespace {
const double kNan = std::nan("");
TrackPoint pt(double t_s, double est, double truth) {
  return TrackPoint{static_cast<uint64_t>(std::llround(t_s * 1e9)) + 5000000000ull, est, truth};
}
}  // namespace

TEST_GROUP(RunMetrics) {};

TEST(RunMetrics, ConstantRelativeError) {
  std::vector<TrackPoint> track;
  for (int i = 0; i < 200; ++i) track.push_back(pt(0.01 * i, 2.2, 2.0));
  const RunMetrics m = compute_metrics(track);
  LONGS_EQUAL(200, m.samples);
  LONGS_EQUAL(200, m.with_truth);
  LONGS_EQUAL(0, m.excluded_slow);
  DOUBLES_EQUAL(10.0, m.e_percent, 1e-9);
  DOUBLES_EQUAL(10.0, m.l1_percent, 1e-9);
  DOUBLES_EQUAL(0.2, m.rms, 1e-12);
  DOUBLES_EQUAL(0.2, m.worst_after, 1e-12);
  DOUBLES_EQUAL(0.2, m.mean_after, 1e-12);
  LONGS_EQUAL(100, m.after_count);  // t = 1.00 .. 1.99 s
}

TEST(RunMetrics, EIsATimeAverageAcrossGaps) {
  // 10 ms apart, then a 90 ms gap: the point after the gap weighs 90 ms.
  const std::vector<TrackPoint> track = {pt(0.00, 1.1, 1.0), pt(0.01, 1.1, 1.0), pt(0.02, 1.1, 1.0),
                                         pt(0.11, 1.5, 1.0)};
  const RunMetrics m = compute_metrics(track);
  // weights 10 (median), 10, 10, 90 ms; relative errors .1 .1 .1 .5
  DOUBLES_EQUAL(100 * (0.01 * 0.1 * 3 + 0.09 * 0.5) / 0.12, m.e_percent, 1e-9);
  DOUBLES_EQUAL(100 * 0.8 / 4.0, m.l1_percent, 1e-9);  // L1 is not time-weighted
}

// An hour between two frames weighs 10 median intervals, not the hour (was:
// the frame after the pause weighed 3600 s against 3 s of the rest, and E was
// that one frame's error: 0.26 % for a run whose other frames err by 1 %).
TEST(RunMetrics, APauseWeighsAtMostTenFrameIntervals) {
  std::vector<TrackPoint> track;
  for (int i = 0; i < 20; ++i) track.push_back(pt(0.01 * i, 1.1, 1.0));
  track.push_back(pt(3600.2, 1.5, 1.0));
  const RunMetrics m = compute_metrics(track);
  // weights: 20 x 10 ms at .1, 100 ms at .5
  DOUBLES_EQUAL(100 * (0.2 * 0.1 + 0.1 * 0.5) / 0.3, m.e_percent, 1e-9);
}

TEST(RunMetrics, SlowSamplesAreLeftOutOfEButCounted) {
  const std::vector<TrackPoint> track = {pt(0.00, 1.2, 1.0), pt(0.01, 0.03, 0.01), pt(0.02, 0.8, 1.0),
                                         pt(0.03, -0.049, -0.04)};
  const RunMetrics m = compute_metrics(track);
  LONGS_EQUAL(2, m.excluded_slow);
  DOUBLES_EQUAL(20.0, m.e_percent, 1e-9);
  DOUBLES_EQUAL(100 * (0.2 + 0.02 + 0.2 + 0.009) / (1 + 0.01 + 1 + 0.04), m.l1_percent, 1e-9);
  STRCMP_CONTAINS("2 frames with |V| < 0.05 m/s excluded", format_metrics(m).c_str());
}

TEST(RunMetrics, FirstSecondIsLeftOutOfWorstAndMean) {
  std::vector<TrackPoint> track;
  for (int i = 0; i < 300; ++i) {
    const double t = 0.01 * i;
    const double err = t < 1.0 ? 3.0 : (i == 250 ? -0.4 : 0.1);
    track.push_back(pt(t, 1.0 + err, 1.0));
  }
  const RunMetrics m = compute_metrics(track);
  DOUBLES_EQUAL(0.4, m.worst_after, 1e-12);
  DOUBLES_EQUAL(2.5, m.worst_after_t, 1e-9);
  DOUBLES_EQUAL((199 * 0.1 + 0.4) / 200, m.mean_abs_after, 1e-12);
  DOUBLES_EQUAL((199 * 0.1 - 0.4) / 200, m.mean_after, 1e-12);
  DOUBLES_EQUAL(std::sqrt((100 * 9.0 + 199 * 0.01 + 0.16) / 300), m.rms, 1e-9);  // RMS covers the whole run
}

// A rig standing still, estimated exactly: the worst error, 0, is at the
// first frame after the first second (was: "worst |err| 0 m/s at t = 0.000
// s", a time inside the second the figure leaves out).
TEST(RunMetrics, AnExactRunsWorstErrorIsAfterTheFirstSecond) {
  std::vector<TrackPoint> track;
  for (int i = 0; i < 300; ++i) track.push_back(pt(0.01 * i, 0.0, 0.0));
  const RunMetrics m = compute_metrics(track);
  DOUBLES_EQUAL(0, m.worst_after, 0);
  DOUBLES_EQUAL(1.0, m.worst_after_t, 1e-9);
  STRCMP_CONTAINS("worst |err| 0 m/s at t = 1.000 s", format_metrics(m).c_str());
}

TEST(RunMetrics, PointsWithoutTruthAreIgnored) {
  const std::vector<TrackPoint> track = {pt(0, 5, kNan), pt(0.01, 1.1, 1.0), pt(0.02, 7, kNan)};
  const RunMetrics m = compute_metrics(track);
  LONGS_EQUAL(3, m.samples);
  LONGS_EQUAL(1, m.with_truth);
  DOUBLES_EQUAL(10.0, m.e_percent, 1e-9);
  CHECK(std::isnan(compute_metrics({pt(0, 1, kNan)}).e_percent));
  CHECK(std::isnan(compute_metrics({}).rms));
}

// A ground truth that stops within the first second of a longer run: the
// figures after it are missing for want of truth, not because the run is
// short (was: "no figure: the run lasts 2.990 s").
TEST(RunMetrics, NoTruthAfterTheFirstSecondIsSaidAsSuch) {
  std::vector<TrackPoint> track;
  for (int i = 0; i < 300; ++i) track.push_back(pt(0.01 * i, 1.1, i < 50 ? 1.0 : kNan));
  STRCMP_CONTAINS("after the first 1.0 s: no figure: no frame after it has ground truth (the run lasts 2.990 s)",
                  format_metrics(compute_metrics(track)).c_str());
  track.resize(50);  // a run shorter than the second: that is the reason
  STRCMP_CONTAINS("after the first 1.0 s: no figure: the run lasts 0.490 s", format_metrics(compute_metrics(track)).c_str());
}
