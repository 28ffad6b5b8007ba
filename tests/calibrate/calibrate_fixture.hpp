// Rendering and blind calibration helpers shared by the calibrate suites.
#pragma once
#include <CppUTest/TestHarness.h>
#include <CppUTest/MemoryLeakWarningPlugin.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include "lumavel/host/calibrate.hpp"
#include "lumavel/host/recording.hpp"
#include "lumavel/host/render/recording_renderer.hpp"
#include "lumavel/host/render/scenario_loader.hpp"

namespace lumavel::host::calibrate_test {

// Renders `scenario` at WxH for `duration_s`, misaligned by
// `misalignment_deg` (NaN: the scenario's own), into a fresh temp folder.
inline std::string rendered_misaligned(const char* scenario, int w, int h, double duration_s, double misalignment_deg,
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

inline std::string rendered(const char* scenario, double duration_s, const char* id) {
  return rendered_misaligned(scenario, 160, 120, duration_s, std::nan(""), id);
}

// Renders `scenario` at 160x120 for `duration_s` with the given
// misalignment and calibrates it blind.
inline double calibrated_deg(const char* scenario, double duration_s, double misalignment_deg, const char* id) {
  const std::string dir = rendered_misaligned(scenario, 160, 120, duration_s, misalignment_deg, id);
  const Calibration c = calibrate_misalignment(load_recording(dir));
  std::filesystem::remove_all(dir);
  std::printf("\n  %s, true %.3f deg: calibrated %.4f +- %.4f deg (%zu frames)", scenario, misalignment_deg, c.misalignment * 180 / M_PI,
              c.uncertainty * 180 / M_PI, c.samples);
  CHECK(c.samples > 100);
  return c.misalignment * 180 / M_PI;
}

}  // namespace lumavel::host::calibrate_test
