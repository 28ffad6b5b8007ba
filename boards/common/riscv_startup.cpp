// Minimal RISC-V (RV32, machine mode) start-up shared by RISC-V boards, the
// twin of cortex_m_startup.cpp: _start (placed first by riscv_sections.ld)
// sets the global and stack pointers and the trap vector; the reset function
// copies .data from its load address, zeroes .bss, runs static constructors,
// then main(). Any trap (illegal instruction, misaligned or faulting access,
// ebreak outside a semihosting call) goes to lumavel_fault_handler().
#include <cstdint>

#include "include/lumavel/board/c_runtime.hpp"

extern "C" {

[[noreturn]] void lumavel_reset();
void lumavel_trap_entry();
void lumavel_fault_handler();     // weak: default spins so a debugger/watchdog sees it

__attribute__((weak)) void lumavel_board_early_init() {}
__attribute__((weak)) void lumavel_fault_handler() {
  for (;;) {
  }
}

// gp is set with relaxation off (the linker would otherwise relax this very
// load against gp itself). mtvec in direct mode needs a 4-byte aligned handler.
// Zicsr (the CSR instructions) is named for the assembler only: GCC 12's
// multilib selection knows -march=rv32imac, not rv32imac_zicsr, and binutils
// 2.40 follows the ISA spec that took CSRs out of the base.
__asm__(
    ".section .text.start, \"ax\", @progbits\n"
    ".globl _start\n"
    "_start:\n"
    ".option push\n"
    ".option norelax\n"
    "  la gp, __global_pointer$\n"
    ".option pop\n"
    "  la sp, _estack\n"
    "  la t0, lumavel_trap_entry\n"
    ".option push\n"
    ".option arch, +zicsr\n"
    "  csrw mtvec, t0\n"
    ".option pop\n"
    "  j lumavel_reset\n"
    ".previous\n");

__attribute__((aligned(4))) void lumavel_trap_entry() {
  lumavel_fault_handler();
  for (;;) {
  }
}

void lumavel_reset() {
  lumavel::board::run_c_runtime();
}
}
