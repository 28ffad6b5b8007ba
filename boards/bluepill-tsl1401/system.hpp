// Time base (SysTick, 1 kHz interrupt plus the counter for sub-ms) and the
// independent watchdog.
#pragma once
#include <cstdint>

#include "lumavel/hal/clock.hpp"
#include "lumavel/hal/watchdog.hpp"

namespace bluepill {

class SysTickClock final : public lumavel::hal::Clock {
 public:
  void init();
  uint64_t now_ns() override;
  void delay_ms(uint32_t ms);
};

// IWDG on the 40 kHz LSI: /64, reload 625: about 1 s without a kick resets.
class Iwdg final : public lumavel::hal::Watchdog {
 public:
  void init();
  void kick() override;
};

}  // namespace bluepill
