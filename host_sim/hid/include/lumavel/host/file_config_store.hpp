// hal::ConfigStore on a host file (the flash page of a simulated device).
#pragma once
#include <string>

#include "lumavel/hal/config_store.hpp"

namespace lumavel::host {

class FileConfigStore : public hal::ConfigStore {
 public:
  explicit FileConfigStore(std::string path) : path_(std::move(path)) {}
  size_t load(uint8_t* buf, size_t cap) override;  // 0 if missing or larger than cap
  bool save(const uint8_t* buf, size_t len) override;  // atomic: temp file + rename

 private:
  std::string path_;
};

}  // namespace lumavel::host
