// Minimal Cortex-M start-up shared by the boards: the 16 core vectors, a reset
// handler that copies .data from flash and zeroes .bss itself (QEMU's ELF
// loader and real flash both leave .data at its load address), runs static
// constructors, then main(). Device interrupt vectors, if a board needs them,
// go in section .isr_vector.device right after these.
#include <cstdint>

#include "include/lumavel/board/c_runtime.hpp"

extern "C" {
extern uint32_t _estack[];

void Reset_Handler();
void lumavel_fault_handler();     // weak: default spins so a debugger/watchdog sees it
void lumavel_systick_handler();   // weak: boards that enable the SysTick interrupt define it

__attribute__((weak)) void lumavel_board_early_init() {}
__attribute__((weak)) void lumavel_fault_handler() {
  for (;;) {
  }
}
__attribute__((weak)) void lumavel_systick_handler() { lumavel_fault_handler(); }
// Empty _init/_fini: newlib's __libc_init_array/exit may reference them (-nostartfiles).
__attribute__((weak)) void _init() {}
__attribute__((weak)) void _fini() {}

void Reset_Handler() {
  lumavel::board::run_c_runtime();
}

using Vector = void (*)();
__attribute__((section(".isr_vector"), used)) const Vector lumavel_core_vectors[16] = {
    reinterpret_cast<Vector>(_estack),  // initial stack pointer
    Reset_Handler,
    lumavel_fault_handler,  // NMI
    lumavel_fault_handler,  // HardFault
    lumavel_fault_handler,  // MemManage (v7-M)
    lumavel_fault_handler,  // BusFault (v7-M)
    lumavel_fault_handler,  // UsageFault (v7-M)
    nullptr, nullptr, nullptr, nullptr,
    lumavel_fault_handler,  // SVCall
    lumavel_fault_handler,  // DebugMon
    nullptr,
    lumavel_fault_handler,  // PendSV
    lumavel_systick_handler,
};
}
