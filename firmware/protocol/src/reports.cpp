#include "lumavel/protocol/reports.hpp"

#include "frame.hpp"
#include "wire.hpp"

namespace lumavel::protocol {

using namespace wire;
using frame::fail;
using frame::seal;

namespace {

// Feature reports the mailbox can send.
bool mailbox_id(uint8_t id) { return id == kReportDeviceInfo || id == kReportConfig || id == kReportLens; }

}  // namespace

const char* to_string(ReportError e) {
  switch (e) {
    case ReportError::kOk: return "ok";
    case ReportError::kShort: return "report too short";
    case ReportError::kWrongId: return "wrong report ID";
    case ReportError::kBadVersion: return "unsupported protocol version";
    case ReportError::kBadCrc: return "CRC mismatch";
    case ReportError::kOutOfRange: return "value out of range";
  }
  return "unknown error";
}

size_t encode_measurement(const Measurement& m, uint8_t* buf, size_t cap) {
  if (buf == nullptr || cap < kMeasurementSize) return 0;
  put_u8(buf, 0, kReportMeasurement);
  put_u8(buf, 1, kProtocolVersion);
  put_u16(buf, 2, m.seq);
  put_u64(buf, 4, m.t_ns);
  put_u32(buf, 12, m.frame_index);
  put_i32(buf, 16, m.v);
  put_i64(buf, 20, m.distance);
  put_i32(buf, 28, m.heading);
  put_u16(buf, 32, m.status);
  put_u16(buf, 34, m.overruns);
  put_i32(buf, 36, m.gyro_offset);
  seal(buf, kMeasurementSize);
  return kMeasurementSize;
}

DecodeResult decode_measurement(const uint8_t* buf, size_t len, Measurement& out) {
  const DecodeResult r = frame::check(buf, len, kReportMeasurement, kProtocolVersion, kMeasurementSize, true);
  if (!r.ok()) return r;
  Measurement m{};
  m.seq = get_u16(buf, 2);
  m.t_ns = get_u64(buf, 4);
  m.frame_index = get_u32(buf, 12);
  m.v = get_i32(buf, 16);
  m.distance = get_i64(buf, 20);
  m.heading = get_i32(buf, 28);
  m.status = get_u16(buf, 32);
  m.overruns = get_u16(buf, 34);
  m.gyro_offset = get_i32(buf, 36);
  if (m.heading < -fx::kPiQ28 || m.heading >= fx::kPiQ28) return fail(ReportError::kOutOfRange, "heading");
  if ((m.status & ~kKnownStatusBits) != 0) return fail(ReportError::kOutOfRange, "status");
  out = m;
  return r;
}

size_t encode_device_info(const DeviceInfo& d, uint8_t* buf, size_t cap) {
  if (buf == nullptr || cap < kDeviceInfoSize) return 0;
  for (size_t i = 0; i < kDeviceInfoSize; ++i) buf[i] = 0;
  put_u8(buf, 0, kReportDeviceInfo);
  put_u8(buf, 1, kProtocolVersion);
  put_u8(buf, 2, d.fw_major);
  put_u8(buf, 3, d.fw_minor);
  put_u8(buf, 4, d.fw_patch);
  for (size_t i = 0; i < kBoardNameSize && d.board[i] != '\0'; ++i) {
    buf[5 + i] = static_cast<uint8_t>(d.board[i]);
  }
  put_u16(buf, 21, d.width);
  put_u16(buf, 23, d.height);
  put_u16(buf, 25, d.max_columns);
  put_u16(buf, 27, d.max_rows);
  put_u8(buf, 29, d.max_kernels);
  put_u8(buf, 30, d.config_status);
  put_u8(buf, 31, d.config_source);
  put_u8(buf, 32, d.lens_status);
  put_u8(buf, 33, d.staged);
  seal(buf, kDeviceInfoSize);
  return kDeviceInfoSize;
}

DecodeResult decode_device_info(const uint8_t* buf, size_t len, DeviceInfo& out) {
  const DecodeResult r = frame::check(buf, len, kReportDeviceInfo, kProtocolVersion, kDeviceInfoSize, true);
  if (!r.ok()) return r;
  DeviceInfo d{};
  d.fw_major = buf[2];
  d.fw_minor = buf[3];
  d.fw_patch = buf[4];
  bool ended = false;
  for (size_t i = 0; i < kBoardNameSize; ++i) {
    const uint8_t c = buf[5 + i];
    if (c == 0) {
      ended = true;
    } else if (ended || c < 0x20 || c > 0x7E) {
      return fail(ReportError::kOutOfRange, "board");
    }
    d.board[i] = static_cast<char>(c);
  }
  d.board[kBoardNameSize] = '\0';
  d.width = get_u16(buf, 21);
  d.height = get_u16(buf, 23);
  d.max_columns = get_u16(buf, 25);
  d.max_rows = get_u16(buf, 27);
  d.max_kernels = buf[29];
  d.config_status = buf[30];
  d.config_source = buf[31];
  d.lens_status = buf[32];
  d.staged = buf[33];
  if (d.max_columns == 0 || d.width > d.max_columns) return fail(ReportError::kOutOfRange, "width");
  if (d.max_rows == 0 || d.height > d.max_rows) return fail(ReportError::kOutOfRange, "height");
  if (d.max_kernels == 0) return fail(ReportError::kOutOfRange, "max_kernels");
  if (d.config_status > kMaxConfigStatus) return fail(ReportError::kOutOfRange, "config_status");
  if (d.config_source > kConfigSetByHost) return fail(ReportError::kOutOfRange, "config_source");
  if (d.lens_status > kMaxConfigStatus) return fail(ReportError::kOutOfRange, "lens_status");
  if ((d.staged & ~3u) != 0) return fail(ReportError::kOutOfRange, "staged");
  out = d;
  return r;
}

size_t encode_mailbox_request(uint8_t report_id, uint8_t tag, uint8_t* buf, size_t cap) {
  if (buf == nullptr || cap < kMailboxSize) return 0;
  buf[0] = kReportMailbox;
  buf[1] = kProtocolVersion;
  buf[2] = report_id;
  buf[3] = tag;
  return kMailboxSize;
}

DecodeResult decode_mailbox_request(const uint8_t* buf, size_t len, uint8_t& report_id, uint8_t& tag) {
  const DecodeResult r = frame::check(buf, len, kReportMailbox, kProtocolVersion, kMailboxSize, false);
  if (!r.ok()) return r;
  if (!mailbox_id(buf[2])) return fail(ReportError::kOutOfRange, "report_id");
  report_id = buf[2];
  tag = buf[3];
  return r;
}

namespace {
constexpr size_t kChunkHeader = 7;
static_assert(kChunkHeader + kFeatureChunkData == kFeatureChunkSize, "mailbox chunk layout");
}  // namespace

size_t encode_feature_chunk(const FeatureChunk& c, uint8_t* buf, size_t cap) {
  if (buf == nullptr || cap < kFeatureChunkSize) return 0;
  if (c.length == 0 || c.length > kFeatureChunkData) return 0;
  buf[0] = kReportFeatureChunk;
  buf[1] = kProtocolVersion;
  buf[2] = c.report_id;
  buf[3] = c.tag;
  buf[4] = c.offset;
  buf[5] = c.length;
  buf[6] = c.total;
  for (size_t i = 0; i < kFeatureChunkData; ++i) buf[kChunkHeader + i] = i < c.length ? c.data[i] : 0;
  return kFeatureChunkSize;
}

DecodeResult decode_feature_chunk(const uint8_t* buf, size_t len, FeatureChunk& out) {
  const DecodeResult r = frame::check(buf, len, kReportFeatureChunk, kProtocolVersion, kFeatureChunkSize, false);
  if (!r.ok()) return r;
  FeatureChunk c{};
  c.report_id = buf[2];
  c.tag = buf[3];
  c.offset = buf[4];
  c.length = buf[5];
  c.total = buf[6];
  if (!mailbox_id(c.report_id)) return fail(ReportError::kOutOfRange, "report_id");
  if (c.total == 0 || c.total > kMaxReportSize) return fail(ReportError::kOutOfRange, "total");
  if (c.length == 0 || c.length > kFeatureChunkData) return fail(ReportError::kOutOfRange, "length");
  if (size_t{c.offset} + c.length > c.total) return fail(ReportError::kOutOfRange, "offset");
  for (size_t i = 0; i < kFeatureChunkData; ++i) {
    c.data[i] = i < c.length ? buf[kChunkHeader + i] : 0;
    if (i >= c.length && buf[kChunkHeader + i] != 0) return fail(ReportError::kOutOfRange, "padding");
  }
  out = c;
  return r;
}

size_t feature_chunk_count(size_t n) {
  if (n == 0 || n > kMaxReportSize) return 0;
  return (n + kFeatureChunkData - 1) / kFeatureChunkData;
}

FeatureChunk feature_chunk(const uint8_t* report, size_t n, uint8_t tag, size_t index) {
  FeatureChunk c{};
  const size_t off = index * kFeatureChunkData;
  if (report == nullptr || index >= feature_chunk_count(n)) return c;  // length 0: encodes to nothing
  c.report_id = report[0];
  c.tag = tag;
  c.offset = static_cast<uint8_t>(off);
  c.length = static_cast<uint8_t>(n - off < kFeatureChunkData ? n - off : kFeatureChunkData);
  c.total = static_cast<uint8_t>(n);
  for (size_t i = 0; i < c.length; ++i) c.data[i] = report[off + i];
  return c;
}

}  // namespace lumavel::protocol
