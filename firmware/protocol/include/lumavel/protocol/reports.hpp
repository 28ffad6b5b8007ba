// The lumavel HID reports other than the configuration: encode (device side)
// and decode + validate (host side). Little-endian, packed, report ID first,
// protocol version second, CRC-16 (crc.hpp) of all preceding bytes last.
// Integer only, no heap, no exceptions.
#pragma once
#include <cstddef>
#include <cstdint>

#include "lumavel/units/fixed.hpp"
#include "lumavel/units/status.hpp"
#include "lumavel/protocol/descriptor.hpp"

namespace lumavel::protocol {

// Why a received report was refused (kOk if it was not).
enum class ReportError : uint8_t {
  kOk = 0,
  kShort,       // fewer bytes than the report's size
  kWrongId,     // byte 0 is not the expected report ID
  kBadVersion,  // byte 1 is not kProtocolVersion
  kBadCrc,      // CRC-16 mismatch
  kOutOfRange,  // a field outside its documented range (see `field`)
};
const char* to_string(ReportError e);

// Result of a decode: the error and, for kOutOfRange, the field's name.
struct DecodeResult {
  ReportError error;
  const char* field;  // static string, "" unless kOutOfRange
  bool ok() const { return error == ReportError::kOk; }
};

// Input report 0x01: one per processed frame.
//   off size field
//   0   1    id = 0x01
//   1   1    protocol version
//   2   2    seq            u16, +1 per report sent (wraps); gaps = lost reports
//   4   8    t_ns           u64, frame timestamp (middle of exposure), ns
//   12  4    frame_index    u32
//   16  4    v              SpeedQ16, m/s
//   20  8    distance       DistQ32, m
//   28  4    heading        AngleQ28, rad, in [-pi, pi)
//   32  2    status         StatusFlag bits (bits 11..15 must be 0: kKnownStatusFlags)
//   34  2    overruns       u16, frames dropped since start (saturates at 65535)
//   36  4    gyro_offset    RateQ24, rad/s: zero-rate offset learned at standstill
//   40  2    crc16 of bytes 0..39
struct Measurement {
  uint16_t seq;
  uint64_t t_ns;
  uint32_t frame_index;
  SpeedQ16 v;
  DistQ32 distance;
  AngleQ28 heading;
  uint16_t status;
  uint16_t overruns;
  RateQ24 gyro_offset;
};

// Status bits defined in this protocol version (lumavel/core/status.hpp).
constexpr uint16_t kKnownStatusBits = kKnownStatusFlags;

// Writes kMeasurementSize bytes; returns the size, or 0 if cap is too small.
size_t encode_measurement(const Measurement& m, uint8_t* buf, size_t cap);
DecodeResult decode_measurement(const uint8_t* buf, size_t len, Measurement& out);

// Feature report 0x02 (get): what the device is and how it runs.
//   off size field
//   0   1    id = 0x02
//   1   1    protocol version
//   2   3    firmware version major, minor, patch
//   5   16   board name, NUL-padded ASCII (printable, no NUL inside)
//   21  2    working width  (columns)
//   23  2    working height (rows)
//   25  2    max columns (build capacity)
//   27  2    max rows
//   29  1    max kernels
//   30  1    config_status: ConfigField of the last configuration set (0 = accepted)
//   31  1    config_source: 0 defaults, 1 loaded from the store, 2 set by the host
//   32  1    lens_status: ConfigField of the last lens piece set (0 accepted,
//            kLens out of order or beyond capacity, kMalformed)
//   33  1    staged: bit c = camera c has lens pieces uploaded that no
//            configuration set has taken yet (an upload in progress)
//   34  2    crc16 of bytes 0..33
constexpr size_t kBoardNameSize = 16;
struct DeviceInfo {
  uint8_t fw_major, fw_minor, fw_patch;
  char board[kBoardNameSize + 1];  // NUL-terminated
  uint16_t width, height;
  uint16_t max_columns, max_rows;
  uint8_t max_kernels;
  uint8_t config_status;
  uint8_t config_source;
  uint8_t lens_status;
  uint8_t staged;
};
enum ConfigSource : uint8_t { kConfigDefaults = 0, kConfigStored = 1, kConfigSetByHost = 2 };
// Largest config_status value (ConfigField::kStore in device_config.hpp).
constexpr uint8_t kMaxConfigStatus = 25;

size_t encode_device_info(const DeviceInfo& d, uint8_t* buf, size_t cap);
DecodeResult decode_device_info(const uint8_t* buf, size_t len, DeviceInfo& out);

// Feature report 0x04 (set): asks the device to send feature report
// `report_id` (0x02, 0x03 or 0x05) as input reports 0x84. For USB stacks whose
// application cannot answer GET_REPORT (Linux gadget HID before 6.13).
//   0 id = 0x04, 1 version, 2 report_id, 3 tag
// The tag (any byte; a host counts them) comes back in every chunk of the
// answer, so that an answer to an earlier request is never taken as current.
// A new request replaces one not yet answered.
size_t encode_mailbox_request(uint8_t report_id, uint8_t tag, uint8_t* buf, size_t cap);
DecodeResult decode_mailbox_request(const uint8_t* buf, size_t len, uint8_t& report_id, uint8_t& tag);

// Input report 0x84: bytes [offset, offset + length) of feature report `report_id`.
//   0 id = 0x84, 1 version, 2 report_id, 3 tag (the request's), 4 offset,
//   5 length (1..55), 6 total size of the feature report, 7..61 data (zero
//   padded); 62 bytes, no CRC (the reassembled feature report carries its own).
struct FeatureChunk {
  uint8_t report_id;
  uint8_t tag;
  uint8_t offset;
  uint8_t length;
  uint8_t total;
  uint8_t data[kFeatureChunkData];
};
size_t encode_feature_chunk(const FeatureChunk& c, uint8_t* buf, size_t cap);
DecodeResult decode_feature_chunk(const uint8_t* buf, size_t len, FeatureChunk& out);

// The mailbox answer to {report_id, tag}: feature report `report` (n bytes,
// 1..kMaxReportSize) cut into feature_chunk_count(n) chunks; chunk `index`
// of them. The one cutting rule for every device side.
size_t feature_chunk_count(size_t n);
FeatureChunk feature_chunk(const uint8_t* report, size_t n, uint8_t tag, size_t index);

}  // namespace lumavel::protocol
