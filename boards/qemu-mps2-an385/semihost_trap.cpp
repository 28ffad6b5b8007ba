// The semihosting trap on M-profile Arm (lumavel/board/semihosting.hpp):
// BKPT 0xAB, operation in r0, argument block in r1, result in r0.
#include <cstdint>

#include "lumavel/board/semihosting.hpp"

extern "C" int32_t lumavel_semihost_trap(uint32_t op, const void* args) {
  register uint32_t r0 __asm__("r0") = op;
  register const void* r1 __asm__("r1") = args;
  __asm__ volatile("bkpt 0xAB" : "+r"(r0) : "r"(r1) : "memory");
  return static_cast<int32_t>(r0);
}
