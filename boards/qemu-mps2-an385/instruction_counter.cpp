// SysTick as the benchmark's instruction counter (lumavel/board/instruction_counter.hpp):
// under qemu-system-arm -icount shift=0 every instruction advances virtual
// time by 1 ns, and the MPS2 SysTick runs at 25 MHz, so one tick is 40
// instructions, identically on every run. (DWT CYCCNT is not emulated.)
#include "lumavel/board/instruction_counter.hpp"

#include <cstdint>

namespace lumavel::board::counter {
namespace {

constexpr uint32_t kTickMask = 0x00FFFFFFu;  // 24-bit down-counter

volatile uint32_t& syst_csr() { return *reinterpret_cast<volatile uint32_t*>(0xE000E010u); }
volatile uint32_t& syst_rvr() { return *reinterpret_cast<volatile uint32_t*>(0xE000E014u); }
volatile uint32_t& syst_cvr() { return *reinterpret_cast<volatile uint32_t*>(0xE000E018u); }

}  // namespace

const uint32_t kInstructionsPerTick = 40;

void start() {
  syst_rvr() = kTickMask;
  syst_cvr() = 0;
  syst_csr() = 5u;  // enable, processor clock, no interrupt
}

uint32_t now() { return syst_cvr(); }

uint32_t ticks_between(uint32_t start, uint32_t end) { return (start - end) & kTickMask; }

// A loop of exactly 2 * n instructions (subs, bne).
void spin(uint32_t n) {
  // GCC wraps inline asm in divided syntax; this loop is written in unified syntax.
  __asm__ volatile(".syntax unified\n1: subs %0, %0, #1\n bne 1b\n .syntax divided" : "+l"(n) : : "cc");
}

}  // namespace lumavel::board::counter
