// A scenario of host_sim/scenarios rendered into a folder and loaded: the
// rendered runs' one way to a recording (2 threads, no progress).
#pragma once
#include <string>

#include "lumavel/host/recording.hpp"
#include "lumavel/host/render/recording_renderer.hpp"
#include "lumavel/host/render/scenario_loader.hpp"

namespace lumavel::host::test {

inline Recording render_scenario(const std::string& file, const render::Overrides& overrides, const std::string& out) {
  render::Scenario s = render::load_scenario(std::string(LUMAVEL_SCENARIO_DIR) + "/" + file);
  render::apply_overrides(s, overrides);
  render::RenderOptions ro;
  ro.threads = 2;
  ro.progress = false;
  render::render_recording(s, out, ro);
  return load_recording(out);
}

}  // namespace lumavel::host::test
