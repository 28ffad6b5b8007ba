// A device configuration with its lens tables as KEY=VALUE text in physical
// units: what `lumavel-read config get` prints, `config set` and
// `config set --file` read, and `lumavel-sim calibrate --write` writes.
// Values print as the shortest decimals that convert back to the same
// fixed-point numbers, so get -> set is lossless.
#pragma once
#include <string>
#include <vector>

#include "lumavel/core/fixed.hpp"
#include "lumavel/protocol/device_config.hpp"

namespace lumavel::host {

struct DeviceSetup {
  protocol::DeviceConfig config{};
  // Lens correction per camera (width + 1 values, EdgeOffsetQ15); empty = pinhole.
  std::vector<EdgeOffsetQ15> lens[2];
};

// One KEY=VALUE per line, every key, in a fixed order (lens_camN=none
// for a camera without a table).
std::string format_setup(const DeviceSetup& s);
// Applies "KEY=VALUE"; throws std::runtime_error naming the key and the
// accepted form. Range checks come afterwards (check_setup, validate()).
void apply_setting(DeviceSetup& s, const std::string& kv);
// Applies every KEY=VALUE line of `text` (blank lines and # comments
// skipped); errors are prefixed with "NAME:LINE: ".
void apply_settings_text(DeviceSetup& s, const std::string& text, const std::string& name);
// Reads FILE and applies it; throws naming the file (and line) on failure.
void apply_settings_file(DeviceSetup& s, const std::string& path);
// Sets config.lens and config.lens_crc from the tables. Throws naming the
// key (lens_camN) when a table's length is not width + 1.
void seal_lens(DeviceSetup& s);
const char* config_keys_help();

}  // namespace lumavel::host
