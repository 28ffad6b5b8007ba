// CRC-16/CCITT-FALSE (poly 0x1021, init 0xFFFF, no reflection, no final xor):
// guards every lumavel report and the stored configuration blob.
#pragma once
#include <cstddef>
#include <cstdint>

namespace lumavel::protocol {

constexpr uint16_t kCrcInit = 0xFFFFu;

// Continues `crc` over `len` bytes (pass kCrcInit to start).
uint16_t crc16(const uint8_t* data, size_t len, uint16_t crc = kCrcInit);

}  // namespace lumavel::protocol
