// Misalignment self-calibration on rendered rigs whose misalignment is known
// to the renderer but not given to the calibration.
#include <CppUTest/TestHarness.h>
#include <CppUTest/MemoryLeakWarningPlugin.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <filesystem>
#include <string>

#include "lumavel/host/calibrate.hpp"
#include "lumavel/host/recording.hpp"
#include "lumavel/host/render/recording_renderer.hpp"
#include "lumavel/host/render/scenario_loader.hpp"

using namespace lumavel::host;

namespace {

// Renders `scenario` at WxH for `duration_s`, misaligned by
// `misalignment_deg` (NaN: the scenario's own), into a fresh temp folder.
std::string rendered_misaligned(const char* scenario, int w, int h, double duration_s, double misalignment_deg,
                                const char* id) {
  render::Scenario s = render::load_scenario(std::string(LUMAVEL_SCENARIOS) + "/" + scenario);
  render::Overrides o;
  o.width = w;
  o.height = h;
  o.duration_s = duration_s;
  render::apply_overrides(s, o);
  if (!std::isnan(misalignment_deg)) s.camera.misalignment_deg = misalignment_deg;
  const std::string dir = (std::filesystem::temp_directory_path() / (std::string("lumavel_calib_") + id)).string();
  std::filesystem::remove_all(dir);
  render::RenderOptions ro;
  ro.progress = false;
  render::render_recording(s, dir, ro);
  return dir;
}

std::string rendered(const char* scenario, double duration_s, const char* id) {
  return rendered_misaligned(scenario, 160, 120, duration_s, std::nan(""), id);
}

// Renders `scenario` at 160x120 for `duration_s` with the given
// misalignment and calibrates it blind.
double calibrated_deg(const char* scenario, double duration_s, double misalignment_deg, const char* id) {
  const std::string dir = rendered_misaligned(scenario, 160, 120, duration_s, misalignment_deg, id);
  const Calibration c = calibrate_misalignment(load_recording(dir));
  std::filesystem::remove_all(dir);
  std::printf("\n  %s, true %.3f deg: calibrated %.4f +- %.4f deg (%zu frames)", scenario, misalignment_deg, c.misalignment * 180 / M_PI,
              c.uncertainty * 180 / M_PI, c.samples);
  CHECK(c.samples > 100);
  return c.misalignment * 180 / M_PI;
}

}  // namespace

// yaml-cpp and the recording library keep function-local statics that the
// per-test leak check would report; AddressSanitizer covers real leaks.
TEST_GROUP(Calibrate) {
  void setup() override { MemoryLeakWarningPlugin::saveAndDisableNewDeleteOverloads(); }
  void teardown() override { MemoryLeakWarningPlugin::restoreNewDeleteOverloads(); }
};

// Issue target: within 0.1 deg of the truth on rigs misaligned by up to 3 deg.
// The paper's rig: 0.5 m/s past a sinusoid-painted plane.
TEST(Calibrate, PaperRigWithinATenthOfADegreeUpToThreeDegrees) {
  DOUBLES_EQUAL(3.0, calibrated_deg("paper_sim_misaligned.yaml", 3, 3.0, "p3"), 0.1);
  DOUBLES_EQUAL(-2.0, calibrated_deg("paper_sim_misaligned.yaml", 3, -2.0, "m2"), 0.1);
  DOUBLES_EQUAL(0.0, calibrated_deg("paper_sim_misaligned.yaml", 3, 0.0, "z"), 0.1);
}

// The hard case: 3.5 m/s past one photo-painted plane at 60 Hz, so no frame
// puts cam0 where cam1 was (5.8 cm a frame, 8 cm baseline) and on a single
// plane a translation looks almost like a rotation: only the zero-translation
// regression across the view takes it out (-0.30 deg of bias without it).
TEST(Calibrate, FastPhotoWallWithinATenthOfADegreeAtThreeDegrees) {
  DOUBLES_EQUAL(3.0, calibrated_deg("robustness_wall.yaml", 4, 3.0, "w3"), 0.1);
  DOUBLES_EQUAL(-3.0, calibrated_deg("robustness_wall.yaml", 4, -3.0, "wm3"), 0.1);
}

// A gyro that does not match the images (50 rad/s about z while the rig
// goes straight) made calibrate answer 65 deg, far outside the +-6 deg it
// searches, with exit 0: no answer outside the search range.
TEST(Calibrate, NoAnswerOutsideTheSearchRange) {
  const std::string dir = rendered("robustness_wall.yaml", 1.5, "spin");
  const Recording good = load_recording(dir);
  Recording spinning = good;
  for (ImuSample& s : spinning.imu_samples) s.w[2] = 50;  // the renderer's imu is body-aligned
  DOUBLES_EQUAL(50, body_yaw_rate(spinning.imu, spinning.imu_samples[0]), 1e-12);
  std::string error = "(no error)";
  try {
    calibrate_misalignment(spinning);
  } catch (const std::runtime_error& e) {
    error = e.what();
  }
  STRCMP_CONTAINS("outside the +-6 deg searched", error.c_str());
  CHECK(std::fabs(calibrate_misalignment(good).misalignment) < 0.1 * M_PI / 180);  // the same frames, intact
  std::filesystem::remove_all(dir);
}

// At 40 columns the paper's rig misaligned by -3 deg calibrated to -2.64 deg
// with a quoted 0.04 deg (8 sigma off) and calibrate suggested sending it.
// The uncertainty now carries the registration's resolution floor: the truth
// lies within 2 sigma, and the sigma is above the 0.1 deg that calibrate
// requires before it suggests a value.
TEST(Calibrate, CoarseRegistrationSaysItCannotKnow) {
  const std::string dir = rendered_misaligned("paper_sim_misaligned.yaml", 40, 30, 4, -3.0, "coarse");
  const Calibration c = calibrate_misalignment(load_recording(dir));
  std::filesystem::remove_all(dir);
  const double err_deg = c.misalignment * 180 / M_PI + 3.0, sigma_deg = c.uncertainty * 180 / M_PI;
  std::printf("\n  40x30, true -3 deg: error %+.3f deg, uncertainty %.3f deg", err_deg, sigma_deg);
  CHECK(std::fabs(err_deg) <= 2 * sigma_deg);
  CHECK(sigma_deg > 0.1);
}
