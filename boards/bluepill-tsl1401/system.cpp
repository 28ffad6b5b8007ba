#include "system.hpp"

#include "clock_tree.hpp"
#include "stm32f1.hpp"

namespace {
volatile uint32_t g_ms = 0;
constexpr uint32_t kTicksPerMs = bluepill::kSysclkHz / 1000;
}  // namespace

extern "C" void lumavel_systick_handler() { g_ms = g_ms + 1; }

namespace bluepill {

void SysTickClock::init() {
  stm32::systick::rvr() = kTicksPerMs - 1;
  stm32::systick::cvr() = 0;
  stm32::systick::csr() = 7u;  // processor clock, interrupt, enable
}

uint64_t SysTickClock::now_ns() {
  uint32_t ms, cvr;
  do {  // re-read if the millisecond interrupt came in between
    ms = g_ms;
    cvr = stm32::systick::cvr();
  } while (ms != g_ms);
  const uint32_t sub = kTicksPerMs - 1 - cvr;  // ticks into this millisecond
  return uint64_t{ms} * 1000000u + uint64_t{sub} * 125u / 9u;  // 1 tick = 1000/72 ns
}

void SysTickClock::delay_ms(uint32_t ms) {
  const uint64_t end = now_ns() + uint64_t{ms} * 1000000u;
  while (now_ns() < end) {
  }
}

void Iwdg::init() {
  stm32::iwdg::kr() = 0x5555;  // unlock PR/RLR
  stm32::iwdg::pr() = 4;       // /64
  stm32::iwdg::rlr() = 625;
  stm32::iwdg::kr() = 0xCCCC;  // start
}

void Iwdg::kick() { stm32::iwdg::kr() = 0xAAAA; }

}  // namespace bluepill
