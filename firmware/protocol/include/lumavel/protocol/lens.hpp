// Lens tables over HID: feature report 0x05 carries a piece of one camera's
// table of column-edge corrections (EdgeOffsetQ15, see EstimatorConfig::
// edge_offsets), small enough for one 64-byte-class transfer and one mailbox
// chunk. The configuration (0x03) says which cameras have a table and binds
// them with lens_crc; the device stages uploaded pieces apart from the
// tables in force (LensTables; app::FeatureServer on a device).
// Integer only, no heap.
#pragma once
#include <cstddef>
#include <cstdint>

#include "lumavel/units/fixed.hpp"
#include "lumavel/units/limits.hpp"
#include "lumavel/protocol/reports.hpp"

namespace lumavel::protocol {

// Offsets per lens report: 6 reports carry a 128-column camera's 129 edges.
constexpr size_t kLensChunkEdges = 24;
// Edges a device can hold per camera (its build's columns + 1).
constexpr size_t kMaxLensEdges = static_cast<size_t>(kMaxColumns) + 1;

// Feature report 0x05 (set: upload or select; get: the selected piece).
//   off size field
//   0   1    id = 0x05
//   1   1    protocol version
//   2   1    camera (0 or 1)
//   3   1    first edge (0..254)
//   4   1    count: 1..24 offsets that follow; 0 = "select": the next get of
//            0x05 (or the mailbox) returns the piece starting at `first`
//   5   48   offsets[24], EdgeOffsetQ15 (i16), rad; slots >= count are 0
//   53  2    crc16 of bytes 0..52
// A get answers with the stored values from `first` on (count = how many of
// the 24 exist, 0 past the end of the table or for a camera without one).
struct LensChunk {
  uint8_t camera;
  uint8_t first;
  uint8_t count;
  EdgeOffsetQ15 offsets[kLensChunkEdges];
};
size_t encode_lens_chunk(const LensChunk& c, uint8_t* buf, size_t cap);
// Length, ID, version, CRC; then camera, count <= 24, first + count <= 255
// and zero unused slots ("camera", "count", "first", "padding").
DecodeResult decode_lens_chunk(const uint8_t* buf, size_t len, LensChunk& out);

// A table of `edges` values (width + 1) for camera `camera`, cut into
// lens_piece_count(edges) upload pieces; piece `index` holds the values from
// index * 24 on (24, fewer in the last). Sent in order, they fill the table.
// The one cutting rule for every sender (host tools, test streams).
size_t lens_piece_count(size_t edges);
LensChunk lens_piece(uint8_t camera, const EdgeOffsetQ15* table, size_t edges, size_t index);

// Lens tables of both cameras, `filled[cam]` edges from 0 on: on a device,
// the tables in force and, apart, the staging that uploads go to
// (app::FeatureServer). Uploads run in order: a piece must start at 0 (starting
// the table again) or where the previous one ended.
struct LensTables {
  EdgeOffsetQ15 offsets[2][kMaxLensEdges];
  uint16_t filled[2];
  uint8_t select_camera;  // piece a get returns
  uint8_t select_first;
};

// Applies one decoded piece (upload or select). False if it does not fit
// the build's capacity or breaks the upload order (nothing changes then).
bool store_lens_chunk(LensTables& t, const LensChunk& c);
// The selected piece, for a get.
LensChunk selected_lens_chunk(const LensTables& t);

// CRC-16 of the present tables (bit b of `lens` = camera b), each `edges`
// values as little-endian i16, camera 0 first; 0 when `lens` is 0. The
// configuration's lens_crc must equal it.
uint16_t lens_crc(const EdgeOffsetQ15* const tables[2], uint8_t lens, uint16_t edges);

}  // namespace lumavel::protocol
