// The lumavel-read subcommands. Each returns the process exit code.
#pragma once
#include <string>
#include <vector>

#include "hidapi_loader.hpp"

namespace lumavel::read {

enum Exit : int {
  kExitOk = 0,
  kExitUsage = 1,
  kExitMalformed = 2,  // malformed reports were seen (and reported)
  kExitNoDevice = 3,
  kExitPermission = 4,
  kExitRefused = 5,    // the device refused a configuration
};

struct Common {
  Backend backend = Backend::kHidraw;
  std::string device;  // hidapi path; empty = first lumavel device
};

int cmd_list(const Common& c, const std::vector<std::string>& args);
int cmd_stream(const Common& c, const std::vector<std::string>& args);
int cmd_info(const Common& c, const std::vector<std::string>& args);
int cmd_config(const Common& c, const std::vector<std::string>& args);
int cmd_replay(const Common& c, const std::vector<std::string>& args);

bool wants_help(const std::vector<std::string>& args);

}  // namespace lumavel::read
