// mcycle as the benchmark's instruction counter (lumavel/board/instruction_counter.hpp):
// under -icount shift=0 QEMU (7.2) derives the cycle counters from its
// virtual clock, which advances 1 ns per instruction, so mcycle counts
// instructions exactly. A CSR read ends QEMU's translation block, so the
// count is exact at every read.
#include "lumavel/board/instruction_counter.hpp"

#include <cstdint>

namespace lumavel::board::counter {

const uint32_t kInstructionsPerTick = 1;

void start() {}

uint32_t now() {
  uint32_t c;
  // Zicsr for the assembler only (see common/riscv_startup.cpp).
  __asm__ volatile(".option push\n .option arch, +zicsr\n csrr %0, mcycle\n .option pop" : "=r"(c));
  return c;
}

uint32_t ticks_between(uint32_t start, uint32_t end) { return end - start; }

// A loop of exactly 2 * n instructions (addi, bnez).
void spin(uint32_t n) { __asm__ volatile("1: addi %0, %0, -1\n bnez %0, 1b" : "+r"(n)); }

}  // namespace lumavel::board::counter
