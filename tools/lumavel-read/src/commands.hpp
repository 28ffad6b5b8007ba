// The lumavel-read commands, after their command lines are parsed (main.cpp).
// Each returns the process exit status.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "hidapi_loader.hpp"
#include "lumavel/host/config_text.hpp"

namespace lumavel::read {

// 0 and 1 and 2 as every lumavel tool (lumavel/host/cli.hpp); 3.. are ours.
enum Exit : int {
  kExitOk = 0,
  kExitFailure = 1,    // bad input (configuration refused before sending, malformed reports) or failure
  kExitUsage = 2,
  kExitNoDevice = 3,
  kExitPermission = 4,
  kExitRefused = 5,    // the device (or its current configuration) refused a configuration
};

struct Common {
  std::string backend = "hidraw";
  std::string device;  // hidapi path; empty = first lumavel device
  Backend backend_kind() const { return parse_backend(backend); }
};

struct StreamOptions {
  std::string output;
  uint64_t count = 0;      // 0: until interrupted
  double timeout_s = 0;    // 0: wait forever
  bool no_reconnect = false;
  bool live = false, no_live = false;
  bool csv_on_tty = false;
};

// The settings of `config set` / `config check`: files first, then KEY=VALUE.
struct ConfigInput {
  std::vector<std::string> files;
  std::vector<std::string> settings;
  // Reads and checks them without any device (check_settings_offline);
  // throws std::runtime_error naming the file, line, key, value and rule.
  host::GivenSettings read_and_check() const;
};

int cmd_list(const Common& c);
int cmd_stream(const Common& c, const StreamOptions& o);
int cmd_info(const Common& c);
int cmd_config_get(const Common& c);
int cmd_config_set(const Common& c, const ConfigInput& in);
int cmd_config_check(const ConfigInput& in);
int cmd_replay(const std::string& file, const StreamOptions& o);

}  // namespace lumavel::read
