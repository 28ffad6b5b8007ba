// Gyro zero-rate offset end to end (issue 6): host_sim/scenarios/
// gyro_offset_standstill.yaml rendered at 80x60 for 6 s (2 s standstill in
// front of a photo wall 2 m away, 1.5 s smooth start to 0.8 m/s, then turning),
// with its 2 deg/s offset and MPU-6050-like gyro noise, and from the same seed
// without the offset; estimated at the product's 40x30 by both engines, with
// the offset learned at standstill (the default) and without.
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>

#include "offset_runs.hpp"
// CppUTest last: its leak-detector macros redefine new.
#include "CppUTest/TestHarness.h"
#include "CppUTest/MemoryLeakWarningPlugin.h"

using namespace lumavel::host;
using namespace lumavel::host::gyro_test;

namespace {

constexpr double kRadPerDeg = 3.14159265358979323846 / 180;
constexpr EngineKind kEngines[] = {EngineKind::kFixed, EngineKind::kFloat};

// Rendered once per process into a folder removed at exit (2 s; 5 s under ASan).
class Renders {
 public:
  Renders() : dir_(std::filesystem::temp_directory_path() / ("lumavel_gyro_test_" + std::to_string(::getpid()))) {
    std::filesystem::remove_all(dir_);
    r_ = render_both(std::string(LUMAVEL_SCENARIO_DIR) + "/gyro_offset_standstill.yaml", 80, 60, 6.0, dir_.string());
  }
  ~Renders() {
    std::error_code ec;
    std::filesystem::remove_all(dir_, ec);
  }
  const Rendered& get() const { return r_; }

 private:
  std::filesystem::path dir_;
  Rendered r_;
};

const Rendered& rendered() {
  static Renders r;
  return r.get();
}

OffsetRun estimate(bool with_offset, EngineKind engine, bool learning) {
  const Rendered& r = rendered();
  const OffsetRun o = run_offset(with_offset ? r.with_offset : r.without_offset, r, engine, learning, 40, 30);
  std::printf("\n  %s offset, %s, learning %s: %s", with_offset ? "2 deg/s" : "no", engine_name(engine),
              learning ? "on" : "off", describe(o).c_str());
  return o;
}

}  // namespace

// The render is kept for the whole process on purpose (see Renders), and
// yaml-cpp allocates statics on first use: not leaks of the code under test.
TEST_GROUP(GyroOffset) {
  void setup() override { MemoryLeakWarningPlugin::saveAndDisableNewDeleteOverloads(); }
  void teardown() override { MemoryLeakWarningPlugin::restoreNewDeleteOverloads(); }
};

TEST(GyroOffset, ScenarioIsAStandstillOfTwoSecondsWithATwoDegPerSecondOffset) {
  const Rendered& r = rendered();
  DOUBLES_EQUAL(2.0, r.still_end_s, 0);
  DOUBLES_EQUAL(2.0 * kRadPerDeg, r.scenario.imu.gyro_bias_z, 1e-12);
}

// Measured: 1.9992 deg/s (both engines), flagged still for 1.68 s, last at
// 2.18 s. The gyro noise (8.7e-5 rad/s/sqrt(Hz)) averaged over the ~1.5 s of
// stillness leaves sigma ~ 7e-5 rad/s = 0.004 deg/s: bound 0.02 deg/s (5 sigma).
// The smooth start covers still_distance (2 mm) only after 0.19 s, so the
// last still frame may be that far into the motion (bound 0.3 s); the start
// is straight, so the gyro still reads the offset alone there.
TEST(GyroOffset, LearnedAtStandstillMatchesTheTrueOffset) {
  const Rendered& r = rendered();
  for (EngineKind engine : kEngines) {
    const OffsetRun o = estimate(true, engine, true);
    DOUBLES_EQUAL(r.scenario.imu.gyro_bias_z, o.offset, 0.02 * kRadPerDeg);
    // Still from still_min (0.5 s) after the first frame to the end of the
    // standstill, and never once the rig moves.
    CHECK(o.still_s > r.still_end_s - 0.5 - 0.1);
    CHECK(o.last_still_t < r.still_end_s + 0.3);
  }
}

// Learned, V is as good as with an offset-free gyro. Measured (both engines):
// mean error at standstill (1 to 2 s) +0.0002 m/s, cruising (3.5 to 6 s)
// +0.0018 m/s, the same as without offset to 1e-4; E 7.68 % in both (the
// acceleration's lag of V with tau = 0.1 s dominates E). Bounds: 0.005 and
// 0.01 m/s absolute, 0.002 m/s and 0.2 point from the offset-free run; the
// offset uncorrected costs ~0.07 m/s (next test).
TEST(GyroOffset, VIsRightAfterTheStandstillWithLearning) {
  for (EngineKind engine : kEngines) {
    const OffsetRun learned = estimate(true, engine, true), clean = estimate(false, engine, true);
    CHECK(std::fabs(learned.mean_err_still) < 0.005);
    CHECK(std::fabs(learned.mean_err_cruise) < 0.01);
    CHECK(std::fabs(learned.mean_err_cruise - clean.mean_err_cruise) < 0.002);
    CHECK(learned.metrics.e_percent < clean.metrics.e_percent + 0.2);
  }
}

// Without learning the offset reads as image motion: V off by about the offset
// times the wall distance (0.035 rad/s x 2 to 2.5 m = 0.07 to 0.087 m/s).
// Measured +0.0710 m/s at standstill, +0.0787 m/s cruising; bound 0.05 m/s.
TEST(GyroOffset, VIsClearlyWrongWithoutLearning) {
  for (EngineKind engine : kEngines) {
    const OffsetRun raw = estimate(true, engine, false);
    CHECK(raw.still_s == 0);
    CHECK(raw.offset == 0);
    CHECK(raw.mean_err_still > 0.05);
    CHECK(raw.mean_err_cruise > 0.05);
  }
}

// With an offset-free gyro the learned offset is the noise's mean (measured
// -0.0008 deg/s) and V does not change: cruising mean error +0.0018 m/s and E
// 7.68 / 7.67 % either way. Bounds as above.
TEST(GyroOffset, LearningDoesNotHurtWithoutOffset) {
  for (EngineKind engine : kEngines) {
    const OffsetRun learning = estimate(false, engine, true), raw = estimate(false, engine, false);
    DOUBLES_EQUAL(0.0, learning.offset, 0.02 * kRadPerDeg);
    CHECK(std::fabs(learning.mean_err_cruise - raw.mean_err_cruise) < 0.002);
    CHECK(std::fabs(learning.metrics.e_percent - raw.metrics.e_percent) < 0.1);
  }
}
