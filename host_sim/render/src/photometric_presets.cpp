#include "lumavel/host/render/photometric_presets.hpp"

namespace lumavel::host::render {
namespace {

// Two cheap board cameras of the same model, each with its own lens and
// auto-exposure: cam1 20 % brighter, black level 20 % higher, corner
// fall-off 20 % deeper; each with its own draw of the fixed patterns.
std::array<PhotometricSpec, 2> cheap_pair() {
  PhotometricSpec c0;
  c0.gain = 1.0;
  c0.black_level = 10;
  c0.vignetting[0] = -0.36;  // corner 1 - 0.36 + 0.06 = 0.70: 30 % fall-off
  c0.vignetting[1] = 0.06;
  c0.prnu = 0.01;
  c0.dsnu = 1.5;
  c0.column_gain = 0.005;
  c0.column_offset = 0.7;
  PhotometricSpec c1 = c0;
  c1.gain = 1.2;
  c1.black_level = 12;
  c1.vignetting[0] = -0.43;  // corner 1 - 0.43 + 0.07 = 0.64: 36 % fall-off
  c1.vignetting[1] = 0.07;
  return {c0, c1};
}

// The differences issue 10's wall names and nothing else: cam1 15 % less
// gain, black level 10 vs 12, corner fall-off 30 vs 36 %; no fixed pattern
// (what a photometric mapping of smooth responses can learn, without the
// patterns and the brighter camera's clipping that cheap_pair adds).
std::array<PhotometricSpec, 2> differing_pair() {
  PhotometricSpec c0;
  c0.gain = 1.0;
  c0.black_level = 10;
  c0.vignetting[0] = -0.36;
  c0.vignetting[1] = 0.06;
  PhotometricSpec c1 = c0;
  c1.gain = 0.85;
  c1.black_level = 12;
  c1.vignetting[0] = -0.43;
  c1.vignetting[1] = 0.07;
  return {c0, c1};
}

// Twins but for cam1's tone curve (gamma 1.05: another sensor batch or ISP
// setting): a difference that no gain, black level or fall-off maps, and that
// the photometric match does not model (docs/design.md, "Beyond the model").
std::array<PhotometricSpec, 2> tone_pair() {
  PhotometricSpec c0;
  PhotometricSpec c1 = c0;
  c1.gamma = 1.05;
  return {c0, c1};
}

std::array<PhotometricSpec, 2> cheap_pair_auto_exposure() {
  auto cams = cheap_pair();
  for (auto& c : cams) {
    c.auto_exposure.sigma = 0.05;
    c.auto_exposure.interval_s = 1.5;
  }
  return cams;
}

const PhotometricPreset kPresets[] = {
    {"ideal", "photometric twins: no gain, offset, vignetting or fixed pattern", {}},
    {"cheap_pair",
     "cam1 gain x1.20, black level 10 vs 12, corner fall-off 30 vs 36 %,\n"
     "                   PRNU 1 %, DSNU 1.5, column FPN 0.5 % and 0.7",
     cheap_pair()},
    {"differing_pair", "cam1 gain x0.85, black level 10 vs 12, corner fall-off 30 vs 36 %,\n"
                       "                   no fixed pattern",
     differing_pair()},
    {"cheap_pair_ae", "cheap_pair with a free-running auto-exposure per camera\n"
                      "                   (5 % rms, new value every 1.5 s)",
     cheap_pair_auto_exposure()},
    {"tone_pair", "twins but for cam1's tone curve: gamma 1.05 (no model in the match)", tone_pair()},
};

}  // namespace

PhotometricPresetList photometric_presets() { return {kPresets, sizeof kPresets / sizeof kPresets[0]}; }

const PhotometricPreset* find_photometric_preset(const std::string& name) {
  for (const auto& p : photometric_presets())
    if (name == p.name) return &p;
  return nullptr;
}

std::string photometric_preset_names() {
  std::string out;
  for (const auto& p : photometric_presets()) {
    if (!out.empty()) out += ", ";
    out += p.name;
  }
  return out;
}

}  // namespace lumavel::host::render
