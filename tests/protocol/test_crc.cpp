#include <CppUTest/TestHarness.h>

#include <cstring>

#include "lumavel/protocol/crc.hpp"

using lumavel::protocol::crc16;

TEST_GROUP(Crc16){};

TEST(Crc16, CcittFalseCheckValue) {
  // The catalogued check value of CRC-16/CCITT-FALSE.
  const char* s = "123456789";
  CHECK_EQUAL(0x29B1, crc16(reinterpret_cast<const uint8_t*>(s), std::strlen(s)));
}

TEST(Crc16, EmptyIsInit) { CHECK_EQUAL(0xFFFF, crc16(nullptr, 0)); }

TEST(Crc16, ContinuesAcrossCalls) {
  const uint8_t b[] = {1, 2, 3, 4, 5, 6, 7};
  CHECK_EQUAL(crc16(b, 7), crc16(b + 3, 4, crc16(b, 3)));
}

// The definition, a bit at a time: the byte-wise form must give the same CRC
// for every byte value from every register state.
TEST(Crc16, ByteStepEqualsTheBitwiseDefinition) {
  for (uint32_t reg = 0; reg < 0x10000u; reg += 7)
    for (uint32_t byte = 0; byte < 256; ++byte) {
      uint32_t c = reg ^ (byte << 8);
      for (int b = 0; b < 8; ++b) c = ((c & 0x8000u) ? ((c << 1) ^ 0x1021u) : (c << 1)) & 0xFFFFu;
      const uint8_t d = static_cast<uint8_t>(byte);
      LONGS_EQUAL(c, crc16(&d, 1, static_cast<uint16_t>(reg)));
    }
}
