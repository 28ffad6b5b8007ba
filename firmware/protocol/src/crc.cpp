#include "lumavel/protocol/crc.hpp"

namespace lumavel::protocol {

// A byte a step without a table (the polynomial's x^12 + x^5 + 1 applied to
// the byte's top bits folded by x ^ x >> 4): about 10 instructions a byte
// where the bit loop took 40, and no 512-byte table in flash. Computed in
// uint32_t so that no step promotes to signed int.
uint16_t crc16(const uint8_t* data, size_t len, uint16_t crc) {
  uint32_t c = crc;
  for (size_t i = 0; i < len; ++i) {
    uint32_t x = ((c >> 8) ^ data[i]) & 0xFFu;
    x ^= x >> 4;
    c = ((c << 8) ^ (x << 12) ^ (x << 5) ^ x) & 0xFFFFu;
  }
  return static_cast<uint16_t>(c);
}

}  // namespace lumavel::protocol
