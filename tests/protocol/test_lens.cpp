// Lens piece report 0x05 codec, the upload order, and the CRC that binds a
// configuration to its tables.
#include <CppUTest/TestHarness.h>

#include <cstring>

#include "lumavel/protocol/crc.hpp"
#include "lumavel/protocol/device_config.hpp"
#include "lumavel/protocol/lens.hpp"

using namespace lumavel::protocol;
using lumavel::EdgeOffsetQ15;

namespace {

LensChunk sample() {
  LensChunk c{};
  c.camera = 1;
  c.first = 48;
  c.count = 20;
  for (int i = 0; i < 20; ++i) c.offsets[i] = static_cast<EdgeOffsetQ15>(i % 2 ? -32768 + i : 32767 - i);
  return c;
}

void reseal(uint8_t* b) {
  const uint16_t c = crc16(b, kLensChunkSize - 2);
  b[kLensChunkSize - 2] = static_cast<uint8_t>(c);
  b[kLensChunkSize - 1] = static_cast<uint8_t>(c >> 8);
}

}  // namespace

TEST_GROUP(LensChunk){};

TEST(LensChunk, RoundTripsByteExactly) {
  uint8_t a[kLensChunkSize], b[kLensChunkSize];
  CHECK_EQUAL(kLensChunkSize, encode_lens_chunk(sample(), a, sizeof a));
  CHECK_EQUAL(kReportLens, a[0]);
  CHECK_EQUAL(kProtocolVersion, a[1]);
  LensChunk d{};
  CHECK_TRUE(decode_lens_chunk(a, sizeof a, d).ok());
  CHECK_EQUAL(1, d.camera);
  CHECK_EQUAL(48, d.first);
  CHECK_EQUAL(20, d.count);
  MEMCMP_EQUAL(sample().offsets, d.offsets, 20 * sizeof(EdgeOffsetQ15));
  CHECK_EQUAL(0, d.offsets[20]);
  encode_lens_chunk(d, b, sizeof b);
  MEMCMP_EQUAL(a, b, kLensChunkSize);
  // Offsets little-endian from byte 5: 32767 = FF 7F.
  CHECK_EQUAL(0xFF, a[5]);
  CHECK_EQUAL(0x7F, a[6]);
}

TEST(LensChunk, MalformedPiecesAreNamed) {
  uint8_t good[kLensChunkSize], buf[kLensChunkSize];
  encode_lens_chunk(sample(), good, sizeof good);
  LensChunk d{};
  for (size_t n = 0; n < kLensChunkSize; ++n) CHECK_TRUE(ReportError::kShort == decode_lens_chunk(good, n, d).error);
  std::memcpy(buf, good, sizeof buf);
  buf[0] = kReportConfig;
  CHECK_TRUE(ReportError::kWrongId == decode_lens_chunk(buf, sizeof buf, d).error);
  std::memcpy(buf, good, sizeof buf);
  buf[1] = kProtocolVersion + 1;
  CHECK_TRUE(ReportError::kBadVersion == decode_lens_chunk(buf, sizeof buf, d).error);
  for (size_t bit = 16; bit < 8 * kLensChunkSize; ++bit) {
    std::memcpy(buf, good, sizeof buf);
    buf[bit / 8] = static_cast<uint8_t>(buf[bit / 8] ^ (1u << (bit % 8)));
    CHECK_TRUE(ReportError::kBadCrc == decode_lens_chunk(buf, sizeof buf, d).error);
  }
  const struct {
    size_t at;
    uint8_t value;
    const char* field;
  } cases[] = {{2, 2, "camera"}, {4, 25, "count"}, {3, 240, "first"}, {5 + 2 * 23, 1, "padding"}};
  for (const auto& k : cases) {
    std::memcpy(buf, good, sizeof buf);
    buf[k.at] = k.value;
    reseal(buf);
    d.first = 7;
    const DecodeResult r = decode_lens_chunk(buf, sizeof buf, d);
    CHECK_TRUE(ReportError::kOutOfRange == r.error);
    STRCMP_EQUAL(k.field, r.field);
    CHECK_EQUAL(7, d.first);  // untouched
  }
  LensChunk big = sample();
  big.count = 25;
  CHECK_EQUAL(0u, encode_lens_chunk(big, buf, sizeof buf));
  CHECK_EQUAL(0u, encode_lens_chunk(sample(), buf, kLensChunkSize - 1));
}

TEST(LensChunk, UploadRunsInOrderAndSelectsForGet) {
  static LensTables t{};
  LensChunk c{};
  c.camera = 0;
  c.count = 24;
  for (int i = 0; i < 24; ++i) c.offsets[i] = static_cast<EdgeOffsetQ15>(100 + i);
  c.first = 24;
  CHECK_FALSE(store_lens_chunk(t, c));  // nothing before it
  c.first = 0;
  CHECK_TRUE(store_lens_chunk(t, c));
  c.first = 24;
  CHECK_TRUE(store_lens_chunk(t, c));
  CHECK_EQUAL(48, t.filled[0]);
  c.first = 47;
  CHECK_FALSE(store_lens_chunk(t, c));  // overlaps: not where the last one ended
  CHECK_EQUAL(0, t.filled[1]);
  // Select camera 0 from edge 40: 8 values exist.
  LensChunk sel{};
  sel.first = 40;
  CHECK_TRUE(store_lens_chunk(t, sel));
  const LensChunk got = selected_lens_chunk(t);
  CHECK_EQUAL(8, got.count);
  CHECK_EQUAL(100 + 16, got.offsets[0]);
  // Starting again at 0 forgets the rest.
  c.first = 0;
  c.count = 1;
  CHECK_TRUE(store_lens_chunk(t, c));
  CHECK_EQUAL(1, t.filled[0]);
  c.first = static_cast<uint8_t>(kMaxLensEdges - 1);
  c.count = 2;
  CHECK_FALSE(store_lens_chunk(t, c));  // past capacity
}

TEST(LensChunk, CrcCoversNamedTablesInOrder) {
  const EdgeOffsetQ15 a[3] = {1, -2, 3}, b[3] = {4, 5, -6};
  const EdgeOffsetQ15* const ab[2] = {a, b};
  const EdgeOffsetQ15* const ba[2] = {b, a};
  CHECK_EQUAL(0, lens_crc(ab, 0, 3));
  // The bytes of the named tables, little-endian.
  const uint8_t bytes[12] = {1, 0, 0xFE, 0xFF, 3, 0, 4, 0, 5, 0, 0xFA, 0xFF};
  CHECK_EQUAL(crc16(bytes, 12), lens_crc(ab, kLensCam0 | kLensCam1, 3));
  CHECK_EQUAL(crc16(bytes + 6, 6), lens_crc(ab, kLensCam1, 3));
  CHECK(lens_crc(ab, 3, 3) != lens_crc(ba, 3, 3));
}

TEST(LensChunk, StoredBlobRoundTripsAndRefusesMismatch) {
  static LensTables t{}, back{};
  DeviceConfig c = default_device_config();
  for (int u = 0; u <= c.width; ++u) t.offsets[1][u] = static_cast<EdgeOffsetQ15>(u * 37 - 700);
  t.filled[1] = static_cast<uint16_t>(c.width + 1);
  c.lens = kLensCam1;
  const EdgeOffsetQ15* const tables[2] = {nullptr, t.offsets[1]};
  c.lens_crc = lens_crc(tables, c.lens, static_cast<uint16_t>(c.width + 1));
  uint8_t blob[kMaxStoredConfigSize];
  const size_t n = encode_stored_config(c, t, blob, sizeof blob);
  CHECK_EQUAL(kConfigSize + 2 * 41, n);
  DeviceConfig d{};
  CHECK_TRUE(ConfigField::kOk == decode_stored_config(blob, n, d, back));
  CHECK_EQUAL(41, back.filled[1]);
  CHECK_EQUAL(0, back.filled[0]);
  MEMCMP_EQUAL(t.offsets[1], back.offsets[1], 41 * sizeof(EdgeOffsetQ15));
  CHECK_TRUE(ConfigField::kMalformed == decode_stored_config(blob, n - 1, d, back));
  blob[n - 1] ^= 1;
  CHECK_TRUE(ConfigField::kLens == decode_stored_config(blob, n, d, back));
  CHECK_EQUAL(0, back.filled[1]);
  t.filled[1] = 40;  // incomplete: nothing to store
  CHECK_EQUAL(0u, encode_stored_config(c, t, blob, sizeof blob));
}

// The one cutting rule (lens_piece): 24 values a piece, the last one shorter;
// sent in order, the pieces fill the device's table exactly.
TEST(LensChunk, PiecesCutATableThatTheyRefillInOrder) {
  LONGS_EQUAL(0, lens_piece_count(0));
  LONGS_EQUAL(1, lens_piece_count(24));
  LONGS_EQUAL(2, lens_piece_count(25));
  LONGS_EQUAL(6, lens_piece_count(129));  // a 128-column camera
  EdgeOffsetQ15 t[41];
  for (int u = 0; u < 41; ++u) t[u] = static_cast<EdgeOffsetQ15>(u * 700 - 14000);
  static LensTables got{};
  for (size_t i = 0; i < lens_piece_count(41); ++i) {
    const LensChunk c = lens_piece(1, t, 41, i);
    CHECK_EQUAL(1, c.camera);
    CHECK_EQUAL(i * kLensChunkEdges, c.first);
    CHECK_EQUAL(i == 0 ? 24u : 17u, c.count);
    uint8_t b[kLensChunkSize];
    CHECK_EQUAL(kLensChunkSize, encode_lens_chunk(c, b, sizeof b));
    LensChunk back{};
    CHECK_TRUE(decode_lens_chunk(b, sizeof b, back).ok());
    CHECK_TRUE(store_lens_chunk(got, back));
  }
  CHECK_EQUAL(41, got.filled[1]);
  CHECK_EQUAL(0, got.filled[0]);
  MEMCMP_EQUAL(t, got.offsets[1], sizeof t);
}
