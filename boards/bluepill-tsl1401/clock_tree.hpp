// 72 MHz from the 8 MHz crystal: SYSCLK = HSE x 9 (PLL), AHB 72 MHz, APB1 36 MHz
// (I2C, USB registers), APB2 72 MHz (GPIO, ADC), ADC 12 MHz (/6, max 14),
// USB 48 MHz (PLL / 1.5), flash 2 wait states.
#pragma once
#include <cstdint>

namespace bluepill {
constexpr uint32_t kSysclkHz = 72000000;
constexpr uint32_t kApb1Hz = 36000000;
// False if the crystal or the PLL did not start (the board then stays on HSI 8 MHz).
bool clock_tree_init();
}  // namespace bluepill
