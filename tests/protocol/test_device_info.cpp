#include <CppUTest/TestHarness.h>

#include <cstring>

#include "lumavel/protocol/crc.hpp"
#include "lumavel/protocol/reports.hpp"

using namespace lumavel::protocol;

namespace {

DeviceInfo sample() {
  DeviceInfo d{};
  d.fw_major = 0;
  d.fw_minor = 3;
  d.fw_patch = 17;
  std::strcpy(d.board, "nucleo-f411re");
  d.width = 40;
  d.height = 30;
  d.max_columns = 160;
  d.max_rows = 128;
  d.max_kernels = 6;
  d.config_status = 0;
  d.config_source = kConfigStored;
  d.lens_status = 21;  // ConfigField::kLens
  d.staged = 2;
  return d;
}

void reseal(uint8_t* b, size_t size) {
  const uint16_t c = crc16(b, size - 2);
  b[size - 2] = static_cast<uint8_t>(c);
  b[size - 1] = static_cast<uint8_t>(c >> 8);
}

DecodeResult decode_mutated(void (*mutate)(uint8_t*)) {
  uint8_t buf[kDeviceInfoSize];
  encode_device_info(sample(), buf, sizeof buf);
  mutate(buf);
  reseal(buf, sizeof buf);
  DeviceInfo d{};
  return decode_device_info(buf, sizeof buf, d);
}

}  // namespace

TEST_GROUP(DeviceInfo){};

TEST(DeviceInfo, RoundTrips) {
  uint8_t buf[kDeviceInfoSize];
  CHECK_EQUAL(kDeviceInfoSize, encode_device_info(sample(), buf, sizeof buf));
  DeviceInfo d{};
  CHECK_TRUE(decode_device_info(buf, sizeof buf, d).ok());
  CHECK_EQUAL(3, d.fw_minor);
  CHECK_EQUAL(17, d.fw_patch);
  STRCMP_EQUAL("nucleo-f411re", d.board);
  CHECK_EQUAL(40, d.width);
  CHECK_EQUAL(30, d.height);
  CHECK_EQUAL(160, d.max_columns);
  CHECK_EQUAL(128, d.max_rows);
  CHECK_EQUAL(6, d.max_kernels);
  CHECK_EQUAL(kConfigStored, d.config_source);
  CHECK_EQUAL(21, d.lens_status);
  CHECK_EQUAL(2, d.staged);
}

TEST(DeviceInfo, SixteenCharacterBoardNameKept) {
  DeviceInfo s = sample();
  std::strcpy(s.board, "0123456789abcdef");
  uint8_t buf[kDeviceInfoSize];
  encode_device_info(s, buf, sizeof buf);
  DeviceInfo d{};
  CHECK_TRUE(decode_device_info(buf, sizeof buf, d).ok());
  STRCMP_EQUAL("0123456789abcdef", d.board);
}

TEST(DeviceInfo, MalformedRejected) {
  uint8_t buf[kDeviceInfoSize];
  encode_device_info(sample(), buf, sizeof buf);
  DeviceInfo d{};
  CHECK_TRUE(ReportError::kShort == decode_device_info(buf, kDeviceInfoSize - 1, d).error);
  buf[7] ^= 0x10;
  CHECK_TRUE(ReportError::kBadCrc == decode_device_info(buf, sizeof buf, d).error);
  buf[0] = kReportMeasurement;
  CHECK_TRUE(ReportError::kWrongId == decode_device_info(buf, sizeof buf, d).error);
}

TEST(DeviceInfo, OutOfRangeFieldsNamed) {
  STRCMP_EQUAL("board", decode_mutated([](uint8_t* b) { b[6] = 0x07; }).field);
  STRCMP_EQUAL("board", decode_mutated([](uint8_t* b) { b[5 + 14] = 0; b[5 + 15] = 'x'; }).field);
  STRCMP_EQUAL("width", decode_mutated([](uint8_t* b) { b[21] = 161; }).field);
  STRCMP_EQUAL("height", decode_mutated([](uint8_t* b) { b[23] = 129; }).field);
  STRCMP_EQUAL("max_kernels", decode_mutated([](uint8_t* b) { b[29] = 0; }).field);
  STRCMP_EQUAL("config_status", decode_mutated([](uint8_t* b) { b[30] = kMaxConfigStatus + 1; }).field);
  STRCMP_EQUAL("config_source", decode_mutated([](uint8_t* b) { b[31] = 3; }).field);
  STRCMP_EQUAL("lens_status", decode_mutated([](uint8_t* b) { b[32] = kMaxConfigStatus + 1; }).field);
  STRCMP_EQUAL("staged", decode_mutated([](uint8_t* b) { b[33] = 4; }).field);
}

TEST_GROUP(Mailbox){};

TEST(Mailbox, RequestRoundTrips) {
  uint8_t buf[kMailboxSize];
  CHECK_EQUAL(kMailboxSize, encode_mailbox_request(kReportConfig, 0xA7, buf, sizeof buf));
  uint8_t id = 0, tag = 0;
  CHECK_TRUE(decode_mailbox_request(buf, sizeof buf, id, tag).ok());
  CHECK_EQUAL(kReportConfig, id);
  CHECK_EQUAL(0xA7, tag);
}

TEST(Mailbox, RequestForUnknownReportRejected) {
  uint8_t buf[kMailboxSize];
  encode_mailbox_request(kReportMeasurement, 1, buf, sizeof buf);
  uint8_t id = 0, tag = 0;
  CHECK_TRUE(ReportError::kOutOfRange == decode_mailbox_request(buf, sizeof buf, id, tag).error);
  CHECK_TRUE(ReportError::kShort == decode_mailbox_request(buf, 3, id, tag).error);
  encode_mailbox_request(kReportConfig, 1, buf, sizeof buf);
  buf[1] = 2;  // a version 2 request (no tag): not understood
  CHECK_TRUE(ReportError::kBadVersion == decode_mailbox_request(buf, sizeof buf, id, tag).error);
}

TEST(Mailbox, ChunkRoundTrips) {
  FeatureChunk c{};
  c.report_id = kReportConfig;
  c.tag = 0x3C;
  c.offset = 55;
  c.length = 35;
  c.total = 90;
  for (int i = 0; i < 35; ++i) c.data[i] = static_cast<uint8_t>(200 + i);
  uint8_t buf[kFeatureChunkSize];
  CHECK_EQUAL(kFeatureChunkSize, encode_feature_chunk(c, buf, sizeof buf));
  FeatureChunk d{};
  CHECK_TRUE(decode_feature_chunk(buf, sizeof buf, d).ok());
  CHECK_EQUAL(0x3C, d.tag);
  CHECK_EQUAL(55, d.offset);
  CHECK_EQUAL(35, d.length);
  CHECK_EQUAL(90, d.total);
  MEMCMP_EQUAL(c.data, d.data, 35);
  CHECK_EQUAL(0, d.data[35]);
  buf[kFeatureChunkSize - 1] = 1;  // padding must be zero
  STRCMP_EQUAL("padding", decode_feature_chunk(buf, sizeof buf, d).field);
}

TEST(Mailbox, ChunkPastTheEndRejected) {
  FeatureChunk c{};
  c.report_id = kReportConfig;
  c.offset = 60;
  c.length = 31;
  c.total = 90;
  uint8_t buf[kFeatureChunkSize];
  encode_feature_chunk(c, buf, sizeof buf);
  FeatureChunk d{};
  const DecodeResult r = decode_feature_chunk(buf, sizeof buf, d);
  CHECK_TRUE(ReportError::kOutOfRange == r.error);
  STRCMP_EQUAL("offset", r.field);
  c.length = 0;
  CHECK_EQUAL(0u, encode_feature_chunk(c, buf, sizeof buf));
}

TEST(Mailbox, AReportIsCutIntoTaggedChunksThatReassemble) {
  uint8_t report[kMaxReportSize];
  for (size_t i = 0; i < sizeof report; ++i) report[i] = static_cast<uint8_t>(i * 7 + 1);
  report[0] = kReportConfig;
  CHECK_EQUAL(2u, feature_chunk_count(kConfigSize));
  CHECK_EQUAL(1u, feature_chunk_count(kLensChunkSize));
  CHECK_EQUAL(0u, feature_chunk_count(0));
  CHECK_EQUAL(0u, feature_chunk_count(kMaxReportSize + 1));
  uint8_t whole[kMaxReportSize] = {};
  for (size_t i = 0; i < feature_chunk_count(kConfigSize); ++i) {
    const FeatureChunk c = feature_chunk(report, kConfigSize, 0x99, i);
    uint8_t buf[kFeatureChunkSize];
    CHECK_EQUAL(kFeatureChunkSize, encode_feature_chunk(c, buf, sizeof buf));
    FeatureChunk d{};
    CHECK_TRUE(decode_feature_chunk(buf, sizeof buf, d).ok());
    CHECK_EQUAL(0x99, d.tag);
    CHECK_EQUAL(kReportConfig, d.report_id);
    CHECK_EQUAL(kConfigSize, d.total);
    std::memcpy(whole + d.offset, d.data, d.length);
  }
  MEMCMP_EQUAL(report, whole, kConfigSize);
  CHECK_EQUAL(0, feature_chunk(report, kConfigSize, 0, 2).length);  // past the last chunk
}
