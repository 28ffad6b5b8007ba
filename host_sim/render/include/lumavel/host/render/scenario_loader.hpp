// Reads a scenario YAML file. Every key is checked: an unknown key, a missing
// required key or a bad value throws ScenarioError "FILE:LINE: what".
#pragma once
#include <stdexcept>
#include <string>

#include "lumavel/host/render/scenario.hpp"

namespace lumavel::host::render {

class ScenarioError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

Scenario load_scenario(const std::string& path);
// Same from text; `name` stands for the file in messages, relative photo paths
// resolve against `base_dir`.
Scenario parse_scenario(const std::string& text, const std::string& name,
                        const std::string& base_dir = ".");

// Command-line overrides; negative / empty = keep the scenario's value.
struct Overrides {
  int width = -1, height = -1;
  double exposure_frames = -1;
  long long seed = -1;
  double duration_s = -1;
  // Photometric preset for both cameras (photometric_presets.hpp), replacing
  // the scenario's photometric block; unknown names throw ScenarioError.
  std::string camera_mismatch;
};
void apply_overrides(Scenario& s, const Overrides& o);

// The most frame pairs, gyro samples or ground-truth samples one render makes
// (1e7: 46 hours of 60 Hz frames, 14 of 200 Hz ground truth): the samples are
// held in memory and the frames counted in an int.
constexpr double kMaxRenderSamples = 1e7;
// Throws ScenarioError "FILE: ..." when the scenario (overrides applied)
// asks for more of any stream than kMaxRenderSamples, naming its rate and
// duration.
void check_render_size(const Scenario& s);

}  // namespace lumavel::host::render
