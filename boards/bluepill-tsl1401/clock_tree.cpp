#include "clock_tree.hpp"

#include "stm32f1.hpp"

namespace bluepill {

bool clock_tree_init() {
  using namespace stm32;
  rcc::cr() |= 1u << 16;  // HSEON
  uint32_t timeout = 500000;
  while ((rcc::cr() & (1u << 17)) == 0) {  // HSERDY
    if (--timeout == 0) return false;
  }
  flash::acr() = (1u << 4) | 2u;  // prefetch on, 2 wait states (48 < SYSCLK <= 72 MHz)
  rcc::cfgr() = (0x7u << 18)      // PLLMUL x9
                | (1u << 16)      // PLLSRC = HSE
                | (0x2u << 14)    // ADCPRE /6
                | (0x4u << 8);    // PPRE1 /2; HPRE, PPRE2 /1; USBPRE 0: PLL / 1.5
  rcc::cr() |= 1u << 24;          // PLLON
  timeout = 500000;
  while ((rcc::cr() & (1u << 25)) == 0) {  // PLLRDY
    if (--timeout == 0) return false;
  }
  rcc::cfgr() = (rcc::cfgr() & ~0x3u) | 0x2u;  // SW = PLL
  while ((rcc::cfgr() & 0xCu) != 0x8u) {       // SWS = PLL
  }
  return true;
}

}  // namespace bluepill
