// SysTick as an instruction counter: under qemu-system-arm -icount shift=0
// every instruction advances virtual time by 1 ns, and the MPS2 SysTick runs
// at 25 MHz, so one tick is 40 instructions, identically on every run.
// (DWT CYCCNT is not emulated.)
#pragma once
#include <cstdint>

namespace lumavel::qemu {

constexpr uint32_t kInstructionsPerTick = 40;
constexpr uint32_t kTickMask = 0x00FFFFFFu;  // 24-bit down-counter

inline volatile uint32_t& syst_csr() { return *reinterpret_cast<volatile uint32_t*>(0xE000E010u); }
inline volatile uint32_t& syst_rvr() { return *reinterpret_cast<volatile uint32_t*>(0xE000E014u); }
inline volatile uint32_t& syst_cvr() { return *reinterpret_cast<volatile uint32_t*>(0xE000E018u); }

inline void systick_start() {
  syst_rvr() = kTickMask;
  syst_cvr() = 0;
  syst_csr() = 5u;  // enable, processor clock, no interrupt
}

// Kept out of line so that the compiler cannot move measured work across it.
__attribute__((noipa)) uint32_t systick_now();

// Ticks from `start` to `end` of the down-counter (one wrap at most).
inline uint32_t ticks_between(uint32_t start, uint32_t end) { return (start - end) & kTickMask; }

}  // namespace lumavel::qemu
