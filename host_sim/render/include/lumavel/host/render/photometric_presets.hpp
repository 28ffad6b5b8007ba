// Named photometric presets: realistic pairs of cheap cameras, the one place
// their values live (host_sim/scenarios/README.md says where they come from).
// A scenario starts from one with `camera: photometric: preset: NAME`, or the
// render command applies one with `--camera-mismatch NAME`.
#pragma once
#include <array>
#include <string>
#include <cstddef>

#include "lumavel/host/render/scenario.hpp"

namespace lumavel::host::render {

struct PhotometricPreset {
  const char* name;
  const char* what;  // one line for --help
  std::array<PhotometricSpec, 2> cams;  // cam0, cam1
};

// The presets in a fixed table (no heap: built before any test runs).
struct PhotometricPresetList {
  const PhotometricPreset* first;
  size_t count;
  const PhotometricPreset* begin() const { return first; }
  const PhotometricPreset* end() const { return first + count; }
};
PhotometricPresetList photometric_presets();
// nullptr if there is no preset of that name.
const PhotometricPreset* find_photometric_preset(const std::string& name);
// "ideal, cheap_pair, ..." for error messages.
std::string photometric_preset_names();

}  // namespace lumavel::host::render
