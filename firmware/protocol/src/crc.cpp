#include "lumavel/protocol/crc.hpp"

namespace lumavel::protocol {

// Bitwise: 90 bytes at most per report, so a 512-byte table buys nothing.
// Computed in uint32_t so that no step promotes to signed int.
uint16_t crc16(const uint8_t* data, size_t len, uint16_t crc) {
  uint32_t c = crc;
  for (size_t i = 0; i < len; ++i) {
    c ^= static_cast<uint32_t>(data[i]) << 8;
    for (int b = 0; b < 8; ++b) c = (c & 0x8000u) ? ((c << 1) ^ 0x1021u) : (c << 1);
    c &= 0xFFFFu;
  }
  return static_cast<uint16_t>(c);
}

}  // namespace lumavel::protocol
