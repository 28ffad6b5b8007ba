// DeviceConfig as KEY=VALUE text in physical units, for `config get|set`.
#pragma once
#include <string>

#include "lumavel/protocol/device_config.hpp"

namespace lumavel::read {

// One KEY=VALUE per line, every key, in a fixed order.
std::string format_config(const protocol::DeviceConfig& c);
// Applies "KEY=VALUE"; throws std::runtime_error naming the key and the
// accepted form. Range checks are the codec's (validate()), run afterwards.
void apply_setting(protocol::DeviceConfig& c, const std::string& kv);
const char* config_keys_help();

}  // namespace lumavel::read
