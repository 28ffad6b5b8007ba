// An instruction counter for the benchmark (boards/common/semihosting/bench_main.cpp),
// defined by each emulated board in its instruction_counter.cpp. Under QEMU's
// -icount shift=0 every instruction advances virtual time by exactly 1 ns, so
// a clock of the machine counts instructions, identically on every run:
//   MPS2 (Cortex-M): SysTick at 25 MHz, one tick = 40 instructions (24-bit down-counter)
//   RISC-V virt:     the mcycle CSR, which QEMU derives from the same virtual clock: one tick = 1
#pragma once
#include <cstdint>

namespace lumavel::board::counter {

// Instructions per tick of now().
extern const uint32_t kInstructionsPerTick;

void start();
// Out of line and opaque (noipa) so that the compiler cannot move measured work across it.
__attribute__((noipa)) uint32_t now();
// Ticks from `start` to `end` (one wrap of the counter at most).
uint32_t ticks_between(uint32_t start, uint32_t end);
// Runs a loop of exactly 2 * n instructions (n >= 1): the benchmark checks the tick rate on it.
void spin(uint32_t n);

}  // namespace lumavel::board::counter
