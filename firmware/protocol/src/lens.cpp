#include "lumavel/protocol/lens.hpp"

#include "lumavel/protocol/crc.hpp"
#include "frame.hpp"
#include "wire.hpp"

namespace lumavel::protocol {

using namespace wire;
using frame::fail;

namespace {
constexpr size_t kOffsets = 5;
constexpr size_t kCrcAt = kLensChunkSize - 2;
static_assert(kOffsets + 2 * kLensChunkEdges == kCrcAt, "lens report layout");

}  // namespace

size_t encode_lens_chunk(const LensChunk& c, uint8_t* buf, size_t cap) {
  if (buf == nullptr || cap < kLensChunkSize || c.count > kLensChunkEdges) return 0;
  put_u8(buf, 0, kReportLens);
  put_u8(buf, 1, kProtocolVersion);
  put_u8(buf, 2, c.camera);
  put_u8(buf, 3, c.first);
  put_u8(buf, 4, c.count);
  for (size_t i = 0; i < kLensChunkEdges; ++i) {
    const EdgeOffsetQ15 v = i < c.count ? c.offsets[i] : EdgeOffsetQ15{0};
    put_i16(buf, kOffsets + 2 * i, v);
  }
  frame::seal(buf, kLensChunkSize);
  return kLensChunkSize;
}

DecodeResult decode_lens_chunk(const uint8_t* buf, size_t len, LensChunk& out) {
  const DecodeResult r = frame::check(buf, len, kReportLens, kProtocolVersion, kLensChunkSize, true);
  if (!r.ok()) return r;
  LensChunk c{};
  c.camera = buf[2];
  c.first = buf[3];
  c.count = buf[4];
  if (c.camera > 1) return fail(ReportError::kOutOfRange, "camera");
  if (c.count > kLensChunkEdges) return fail(ReportError::kOutOfRange, "count");
  if (size_t{c.first} + c.count > 255) return fail(ReportError::kOutOfRange, "first");
  for (size_t i = 0; i < kLensChunkEdges; ++i) {
    c.offsets[i] = get_i16(buf, kOffsets + 2 * i);
    if (i >= c.count && c.offsets[i] != 0) return fail(ReportError::kOutOfRange, "padding");
  }
  out = c;
  return fail(ReportError::kOk);
}

size_t lens_piece_count(size_t edges) { return (edges + kLensChunkEdges - 1) / kLensChunkEdges; }

LensChunk lens_piece(uint8_t camera, const EdgeOffsetQ15* table, size_t edges, size_t index) {
  LensChunk c{};
  const size_t first = index * kLensChunkEdges;
  c.camera = camera;
  c.first = static_cast<uint8_t>(first);
  const size_t left = first < edges ? edges - first : 0;
  c.count = static_cast<uint8_t>(left < kLensChunkEdges ? left : kLensChunkEdges);
  for (size_t i = 0; i < c.count; ++i) c.offsets[i] = table[first + i];
  return c;
}

bool store_lens_chunk(LensTables& t, const LensChunk& c) {
  if (c.camera > 1 || c.count > kLensChunkEdges) return false;
  if (c.count == 0) {
    t.select_camera = c.camera;
    t.select_first = c.first;
    return true;
  }
  if (size_t{c.first} + c.count > kMaxLensEdges) return false;
  if (c.first != 0 && c.first != t.filled[c.camera]) return false;
  for (size_t i = 0; i < c.count; ++i) t.offsets[c.camera][c.first + i] = c.offsets[i];
  t.filled[c.camera] = static_cast<uint16_t>(c.first + c.count);
  return true;
}

LensChunk selected_lens_chunk(const LensTables& t) {
  LensChunk c{};
  c.camera = t.select_camera;
  c.first = t.select_first;
  const uint16_t have = t.select_camera <= 1 ? t.filled[t.select_camera] : 0;
  const size_t left = c.first < have ? size_t{have} - c.first : 0;
  c.count = static_cast<uint8_t>(left < kLensChunkEdges ? left : kLensChunkEdges);
  for (size_t i = 0; i < c.count; ++i) c.offsets[i] = t.offsets[c.camera][c.first + i];
  return c;
}

uint16_t lens_crc(const EdgeOffsetQ15* const tables[2], uint8_t lens, uint16_t edges) {
  if (lens == 0) return 0;
  uint16_t crc = kCrcInit;
  for (int cam = 0; cam < 2; ++cam) {
    if ((lens & (1u << cam)) == 0 || tables[cam] == nullptr) continue;
    for (uint16_t u = 0; u < edges; ++u) {
      uint8_t b[2];
      put_u16(b, 0, static_cast<uint16_t>(tables[cam][u]));
      crc = crc16(b, 2, crc);
    }
  }
  return crc;
}

}  // namespace lumavel::protocol
