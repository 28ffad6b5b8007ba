// The C runtime start every board's reset code ends in, whatever its core
// (cortex_m_startup.cpp, riscv_startup.cpp): the board's early init (clocks),
// .data copied from its load address, .bss zeroed, static constructors, then
// main(), never returning. The symbols come from the boards' linker sections
// (cortex_m_sections.ld, riscv_sections.ld).
#pragma once
#include <cstdint>

extern "C" {
extern uint32_t _sidata[], _sdata[], _edata[], _sbss[], _ebss[];
using InitFn = void (*)();
extern InitFn __init_array_start[], __init_array_end[];
// ISO C++ forbids calling main(): reach it through another name for the same symbol.
int lumavel_call_main() __asm__("main");
void lumavel_board_early_init();  // weak in the start-up files: clocks before .data/.bss
}

namespace lumavel::board {

[[noreturn]] inline void run_c_runtime() {
  lumavel_board_early_init();
  for (uint32_t *src = _sidata, *dst = _sdata; dst < _edata;) *dst++ = *src++;
  for (uint32_t* dst = _sbss; dst < _ebss;) *dst++ = 0;
  for (InitFn* f = __init_array_start; f < __init_array_end; ++f) (*f)();
  lumavel_call_main();
  for (;;) {
  }
}

}  // namespace lumavel::board
