#pragma once
#include <cstdint>

namespace lumavel::hal {

class Clock {
 public:
  virtual ~Clock() = default;
  virtual uint64_t now_ns() = 0;  // monotonic
};

}  // namespace lumavel::hal
