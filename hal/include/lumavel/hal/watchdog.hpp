#pragma once

namespace lumavel::hal {

class Watchdog {
 public:
  virtual ~Watchdog() = default;
  virtual void kick() = 0;
};

}  // namespace lumavel::hal
