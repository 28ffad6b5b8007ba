// The memory functions that GCC's code generation may call (struct copies,
// zeroing; a counting loop over a string becomes strlen) and <cstring>
// declares, for images linked without a C library (the RISC-V board:
// -nostdlib, libgcc only). Word-wise when both pointers are word-aligned,
// byte-wise otherwise. A board that compiles this file must give it
// -fno-tree-loop-distribute-patterns (so that GCC does not turn these loops
// back into calls to themselves) and -fno-strict-aliasing: see
// boards/qemu-riscv-virt/CMakeLists.txt.
#include <cstddef>
#include <cstdint>
#include <cstring>

namespace {

bool word_aligned(const void* a, const void* b) {
  return ((reinterpret_cast<uintptr_t>(a) | reinterpret_cast<uintptr_t>(b)) & 3u) == 0;
}

}  // namespace

extern "C" {

void* memcpy(void* dst, const void* src, size_t n) {
  auto* d = static_cast<unsigned char*>(dst);
  const auto* s = static_cast<const unsigned char*>(src);
  if (word_aligned(d, s)) {
    for (; n >= 4; n -= 4, d += 4, s += 4) {
      *reinterpret_cast<uint32_t*>(static_cast<void*>(d)) = *reinterpret_cast<const uint32_t*>(static_cast<const void*>(s));
    }
  }
  while (n-- > 0) *d++ = *s++;
  return dst;
}

void* memmove(void* dst, const void* src, size_t n) {
  auto* d = static_cast<unsigned char*>(dst);
  const auto* s = static_cast<const unsigned char*>(src);
  if (d <= s || d >= s + n) return memcpy(dst, src, n);  // forward copy is safe
  while (n-- > 0) d[n] = s[n];
  return dst;
}

void* memset(void* dst, int c, size_t n) {
  auto* d = static_cast<unsigned char*>(dst);
  const auto b = static_cast<unsigned char>(c);
  if (word_aligned(d, d)) {
    const uint32_t w = 0x01010101u * b;
    for (; n >= 4; n -= 4, d += 4) *reinterpret_cast<uint32_t*>(static_cast<void*>(d)) = w;
  }
  while (n-- > 0) *d++ = b;
  return dst;
}

size_t strlen(const char* s) {
  size_t n = 0;
  while (s[n] != '\0') ++n;
  return n;
}

int memcmp(const void* a, const void* b, size_t n) {
  const auto* p = static_cast<const unsigned char*>(a);
  const auto* q = static_cast<const unsigned char*>(b);
  for (size_t i = 0; i < n; ++i) {
    if (p[i] != q[i]) return p[i] < q[i] ? -1 : 1;
  }
  return 0;
}

}  // extern "C"
