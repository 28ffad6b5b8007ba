// Measured stack use: fill the free RAM between .bss and the stack with a
// pattern at start, find the deepest overwritten word at the end.
#pragma once
#include <cstdint>

extern "C" uint32_t _ebss[], _estack[];

namespace lumavel::board {

constexpr uint32_t kStackPattern = 0x5AC3A55Au;

// Called first thing in main(): paints up to a margin below its own frame,
// i.e. below main's whole frame. Not inlined: __builtin_frame_address is the
// bottom of the frame on Thumb but its top (the caller's stack pointer) on
// RISC-V, where an inlined call would paint over main's own locals.
__attribute__((noinline)) inline void paint_stack() {
  uint32_t* limit = static_cast<uint32_t*>(__builtin_frame_address(0)) - 64;
  for (uint32_t* p = _ebss; p < limit; ++p) *p = kStackPattern;
}

// Bytes of stack used so far (from the top of RAM down to the deepest write).
inline uint32_t stack_used() {
  const uint32_t* p = _ebss;
  while (p < _estack && *p == kStackPattern) ++p;
  return static_cast<uint32_t>(reinterpret_cast<uintptr_t>(_estack) - reinterpret_cast<uintptr_t>(p));
}

}  // namespace lumavel::board
