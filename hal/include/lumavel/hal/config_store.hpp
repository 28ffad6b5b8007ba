// Persistent configuration storage (flash page, file, ...): one opaque blob.
#pragma once
#include <cstddef>
#include <cstdint>

namespace lumavel::hal {

class ConfigStore {
 public:
  virtual ~ConfigStore() = default;
  // Bytes read into buf (0 if nothing stored).
  virtual size_t load(uint8_t* buf, size_t cap) = 0;
  virtual bool save(const uint8_t* buf, size_t len) = 0;
};

}  // namespace lumavel::hal
