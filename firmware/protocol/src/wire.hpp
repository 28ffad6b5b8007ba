// Little-endian field access for the report codecs (internal).
#pragma once
#include <cstddef>
#include <cstdint>

namespace lumavel::protocol::wire {

inline void put_u8(uint8_t* b, size_t off, uint8_t v) { b[off] = v; }
inline void put_u16(uint8_t* b, size_t off, uint16_t v) {
  b[off] = static_cast<uint8_t>(v);
  b[off + 1] = static_cast<uint8_t>(v >> 8);
}
inline void put_u32(uint8_t* b, size_t off, uint32_t v) {
  for (size_t i = 0; i < 4; ++i) b[off + i] = static_cast<uint8_t>(v >> (8 * i));
}
inline void put_u64(uint8_t* b, size_t off, uint64_t v) {
  for (size_t i = 0; i < 8; ++i) b[off + i] = static_cast<uint8_t>(v >> (8 * i));
}
inline void put_i16(uint8_t* b, size_t off, int16_t v) { put_u16(b, off, static_cast<uint16_t>(v)); }
inline void put_i32(uint8_t* b, size_t off, int32_t v) { put_u32(b, off, static_cast<uint32_t>(v)); }
inline void put_i64(uint8_t* b, size_t off, int64_t v) { put_u64(b, off, static_cast<uint64_t>(v)); }

inline uint8_t get_u8(const uint8_t* b, size_t off) { return b[off]; }
inline uint16_t get_u16(const uint8_t* b, size_t off) {
  return static_cast<uint16_t>(b[off] | (b[off + 1] << 8));
}
inline uint32_t get_u32(const uint8_t* b, size_t off) {
  uint32_t v = 0;
  for (size_t i = 0; i < 4; ++i) v |= static_cast<uint32_t>(b[off + i]) << (8 * i);
  return v;
}
inline uint64_t get_u64(const uint8_t* b, size_t off) {
  uint64_t v = 0;
  for (size_t i = 0; i < 8; ++i) v |= static_cast<uint64_t>(b[off + i]) << (8 * i);
  return v;
}
// Two's complement reinterpretation, well defined in C++17 via the value's range.
inline int16_t get_i16(const uint8_t* b, size_t off) {
  const uint16_t u = get_u16(b, off);
  return static_cast<int16_t>(u <= 0x7FFF ? int32_t{u} : int32_t{u} - 65536);
}
inline int32_t get_i32(const uint8_t* b, size_t off) {
  const uint32_t u = get_u32(b, off);
  return u <= 0x7FFFFFFFu ? static_cast<int32_t>(u)
                          : -static_cast<int32_t>(~u) - 1;
}
inline int64_t get_i64(const uint8_t* b, size_t off) {
  const uint64_t u = get_u64(b, off);
  return u <= 0x7FFFFFFFFFFFFFFFull ? static_cast<int64_t>(u)
                                    : -static_cast<int64_t>(~u) - 1;
}

}  // namespace lumavel::protocol::wire
