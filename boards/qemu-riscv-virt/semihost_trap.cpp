// The semihosting trap on RISC-V (lumavel/board/semihosting.hpp): operation
// in a0, argument block in a1, result in a0, and the three-instruction
// sequence of the RISC-V semihosting specification, uncompressed (norvc) and
// inside one aligned 16-byte block so that it never straddles a page.
// Also the board's fault handler: a trap (riscv_startup.cpp) exits QEMU with
// status 70, naming the cause and the address, instead of spinning.
#include <cstdint>

#include "lumavel/board/semihosting.hpp"
#include "lumavel/board/text.hpp"

__asm__(
    ".section .text.lumavel_semihost_trap, \"ax\", @progbits\n"
    ".globl lumavel_semihost_trap\n"
    ".type lumavel_semihost_trap, @function\n"
    ".balign 16\n"
    "lumavel_semihost_trap:\n"
    ".option push\n"
    ".option norvc\n"
    "  slli zero, zero, 0x1f\n"
    "  ebreak\n"
    "  srai zero, zero, 7\n"
    ".option pop\n"
    "  ret\n"
    ".size lumavel_semihost_trap, . - lumavel_semihost_trap\n"
    ".previous\n");

extern "C" void lumavel_fault_handler() {
  uint32_t cause, pc, value;
  // Zicsr for the assembler only (see riscv_startup.cpp).
  __asm__ volatile(".option push\n .option arch, +zicsr\n csrr %0, mcause\n csrr %1, mepc\n csrr %2, mtval\n .option pop"
                   : "=r"(cause), "=r"(pc), "=r"(value));
  lumavel::board::Text<120> t;
  t << "trap: mcause " << cause << ", mepc " << pc << ", mtval " << value << " (decimal)\n";
  lumavel::semihost::write_text(t.c_str());
  lumavel::semihost::exit(70);
}
