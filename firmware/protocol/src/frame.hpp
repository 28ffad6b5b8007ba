// Framing shared by the report codecs (internal): report ID first, version
// second, CRC-16 (crc.hpp) of all preceding bytes in the last two.
#pragma once
#include <cstddef>
#include <cstdint>

#include "lumavel/protocol/crc.hpp"
#include "lumavel/protocol/reports.hpp"
#include "wire.hpp"

namespace lumavel::protocol::frame {

inline DecodeResult fail(ReportError e, const char* field = "") { return DecodeResult{e, field}; }

// Length, ID, version and (when crc) CRC of a `size`-byte report.
inline DecodeResult check(const uint8_t* buf, size_t len, uint8_t id, uint8_t version, size_t size, bool crc) {
  if (buf == nullptr || len < size) return fail(ReportError::kShort);
  if (buf[0] != id) return fail(ReportError::kWrongId);
  if (buf[1] != version) return fail(ReportError::kBadVersion);
  if (crc && crc16(buf, size - 2) != wire::get_u16(buf, size - 2)) return fail(ReportError::kBadCrc);
  return fail(ReportError::kOk);
}

// Writes the CRC of the first size - 2 bytes into the last two.
inline void seal(uint8_t* buf, size_t size) { wire::put_u16(buf, size - 2, crc16(buf, size - 2)); }

}  // namespace lumavel::protocol::frame
