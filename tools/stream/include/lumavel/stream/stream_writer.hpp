// Writes the compact stream the emulated board reads (boards/common/stream):
// little-endian fields, one tag per record. Shared by the stream tools.
#pragma once
#include <cstddef>
#include <cstdint>
#include <cstdio>

#include "lumavel/stream/format.hpp"

namespace lumavel::stream {

struct StreamWriter {
  std::FILE* f;
  void bytes(const void* p, size_t n) { std::fwrite(p, 1, n, f); }
  void u8(uint8_t v) { bytes(&v, 1); }
  void u16(uint16_t v) {
    u8(static_cast<uint8_t>(v));
    u8(static_cast<uint8_t>(v >> 8));
  }
  void u64(uint64_t v) {
    for (int i = 0; i < 8; ++i) u8(static_cast<uint8_t>(v >> (8 * i)));
  }
  void i32(int32_t v) {
    const auto u = static_cast<uint32_t>(v);
    for (int i = 0; i < 4; ++i) u8(static_cast<uint8_t>(u >> (8 * i)));
  }
  void header(int width, int height) {
    bytes(kMagic, 4);
    u16(static_cast<uint16_t>(width));
    u16(static_cast<uint16_t>(height));
  }
  void gyro(uint64_t t_ns, int32_t rate_q24) {
    u8(kTagGyro);
    u64(t_ns);
    i32(rate_q24);
  }
};

}  // namespace lumavel::stream
