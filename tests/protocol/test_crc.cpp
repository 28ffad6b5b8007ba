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
