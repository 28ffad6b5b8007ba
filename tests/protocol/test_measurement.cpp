#include <CppUTest/TestHarness.h>

#include <cstring>

#include "lumavel/protocol/crc.hpp"
#include "lumavel/protocol/reports.hpp"

using namespace lumavel::protocol;

namespace {

Measurement sample() {
  Measurement m{};
  m.seq = 0xBEEF;
  m.t_ns = 0x0123456789ABCDEFull;
  m.frame_index = 0x89ABCDEFu;
  m.v = -1234567;                 // -18.8 m/s
  m.distance = -0x123456789ABLL;  // negative and wide
  m.heading = -lumavel::fx::kPiQ28;  // the lower bound is included
  m.status = 0x03D5;  // STILL (bit 7), NO_STEREO (bit 8) and NO_TOF (bit 9) are known bits
  m.overruns = 65535;
  m.gyro_offset = -123457;  // -7.4 mrad/s
  return m;
}

void reseal(uint8_t* b) {
  const uint16_t c = crc16(b, kMeasurementSize - 2);
  b[kMeasurementSize - 2] = static_cast<uint8_t>(c);
  b[kMeasurementSize - 1] = static_cast<uint8_t>(c >> 8);
}

}  // namespace

TEST_GROUP(Measurement){};

TEST(Measurement, RoundTripsEveryField) {
  uint8_t buf[kMeasurementSize];
  const Measurement m = sample();
  CHECK_EQUAL(kMeasurementSize, encode_measurement(m, buf, sizeof buf));
  CHECK_EQUAL(kReportMeasurement, buf[0]);
  CHECK_EQUAL(kProtocolVersion, buf[1]);
  Measurement d{};
  CHECK_TRUE(decode_measurement(buf, sizeof buf, d).ok());
  CHECK_EQUAL(m.seq, d.seq);
  CHECK_TRUE(m.t_ns == d.t_ns);
  CHECK_EQUAL(m.frame_index, d.frame_index);
  CHECK_EQUAL(m.v, d.v);
  CHECK_TRUE(m.distance == d.distance);
  CHECK_EQUAL(m.heading, d.heading);
  CHECK_EQUAL(m.status, d.status);
  CHECK_EQUAL(m.overruns, d.overruns);
  CHECK_EQUAL(m.gyro_offset, d.gyro_offset);
}

TEST(Measurement, LittleEndianLayout) {
  uint8_t buf[kMeasurementSize];
  encode_measurement(sample(), buf, sizeof buf);
  CHECK_EQUAL(0xEF, buf[2]);
  CHECK_EQUAL(0xBE, buf[3]);
  CHECK_EQUAL(0xEF, buf[4]);   // t_ns low byte
  CHECK_EQUAL(0x01, buf[11]);  // t_ns high byte
  // gyro_offset at 36..39, after overruns, before the CRC.
  const uint32_t g = static_cast<uint32_t>(sample().gyro_offset);
  CHECK_EQUAL(g & 0xFF, buf[36]);
  CHECK_EQUAL(g >> 24, buf[39]);
}

TEST(Measurement, EncodeRefusesSmallBuffer) {
  uint8_t buf[kMeasurementSize];
  CHECK_EQUAL(0u, encode_measurement(sample(), buf, kMeasurementSize - 1));
  CHECK_EQUAL(0u, encode_measurement(sample(), nullptr, 100));
}

TEST(Measurement, EveryShortLengthRejected) {
  uint8_t buf[kMeasurementSize];
  encode_measurement(sample(), buf, sizeof buf);
  for (size_t n = 0; n < kMeasurementSize; ++n) {
    Measurement d{};
    CHECK_TRUE(ReportError::kShort == decode_measurement(buf, n, d).error);
  }
}

TEST(Measurement, WrongIdRejected) {
  uint8_t buf[kMeasurementSize];
  encode_measurement(sample(), buf, sizeof buf);
  buf[0] = kReportConfig;
  Measurement d{};
  CHECK_TRUE(ReportError::kWrongId == decode_measurement(buf, sizeof buf, d).error);
}

TEST(Measurement, WrongVersionRejected) {
  uint8_t buf[kMeasurementSize];
  encode_measurement(sample(), buf, sizeof buf);
  buf[1] = kProtocolVersion + 1;
  reseal(buf);
  Measurement d{};
  CHECK_TRUE(ReportError::kBadVersion == decode_measurement(buf, sizeof buf, d).error);
}

TEST(Measurement, EverySingleBitFlipRejected) {
  uint8_t good[kMeasurementSize];
  encode_measurement(sample(), good, sizeof good);
  for (size_t bit = 16; bit < 8 * kMeasurementSize; ++bit) {  // past ID and version
    uint8_t buf[kMeasurementSize];
    std::memcpy(buf, good, sizeof buf);
    buf[bit / 8] = static_cast<uint8_t>(buf[bit / 8] ^ (1u << (bit % 8)));
    Measurement d{};
    CHECK_TRUE(ReportError::kBadCrc == decode_measurement(buf, sizeof buf, d).error);
  }
}

TEST(Measurement, HeadingOutsidePiRejected) {
  Measurement m = sample();
  m.heading = lumavel::fx::kPiQ28;  // +pi is outside [-pi, pi)
  uint8_t buf[kMeasurementSize];
  encode_measurement(m, buf, sizeof buf);
  Measurement d{};
  const DecodeResult r = decode_measurement(buf, sizeof buf, d);
  CHECK_TRUE(ReportError::kOutOfRange == r.error);
  STRCMP_EQUAL("heading", r.field);
  m.heading = -lumavel::fx::kPiQ28 - 1;
  encode_measurement(m, buf, sizeof buf);
  CHECK_TRUE(ReportError::kOutOfRange == decode_measurement(buf, sizeof buf, d).error);
}

TEST(Measurement, UnknownStatusBitRejected) {
  Measurement m = sample();
  for (uint16_t bit = 0; bit < 16; ++bit) {  // the bits status.hpp does not define
    if (lumavel::kKnownStatusFlags & (1u << bit)) continue;
    m.status = static_cast<uint16_t>(1u << bit);
    uint8_t buf[kMeasurementSize];
    encode_measurement(m, buf, sizeof buf);
    Measurement d{};
    const DecodeResult r = decode_measurement(buf, sizeof buf, d);
    CHECK_TRUE(ReportError::kOutOfRange == r.error);
    STRCMP_EQUAL("status", r.field);
  }
}

TEST(Measurement, RejectedDecodeLeavesOutputUntouched) {
  uint8_t buf[kMeasurementSize];
  encode_measurement(sample(), buf, sizeof buf);
  buf[20] ^= 1;
  Measurement d{};
  d.seq = 77;
  decode_measurement(buf, sizeof buf, d);
  CHECK_EQUAL(77, d.seq);
}

TEST(Measurement, ErrorsHaveNames) {
  STRCMP_EQUAL("CRC mismatch", to_string(ReportError::kBadCrc));
  STRCMP_EQUAL("report too short", to_string(ReportError::kShort));
}
