#include <CppUTest/TestHarness.h>

#include "lumavel/protocol/descriptor.hpp"

using namespace lumavel::protocol;

namespace {

// Walks the short items of the descriptor and records, per report ID, the
// byte length of its input and feature reports (ID included).
struct Parsed {
  size_t input[256] = {};
  size_t feature[256] = {};
  unsigned usage_page = 0;
  int depth = 0;
  bool ok = true;
};

Parsed parse() {
  Parsed p;
  unsigned size_bits = 0, count = 0, id = 0;
  size_t i = 0;
  while (i < kReportDescriptorSize) {
    const uint8_t prefix = kReportDescriptor[i];
    const size_t n = (prefix & 3u) == 3u ? 4 : (prefix & 3u);
    if (i + 1 + n > kReportDescriptorSize) {
      p.ok = false;
      break;
    }
    unsigned data = 0;
    for (size_t k = 0; k < n; ++k) data |= unsigned{kReportDescriptor[i + 1 + k]} << (8 * k);
    switch (prefix & 0xFCu) {
      case 0x04: p.usage_page = data; break;
      case 0x74: size_bits = data; break;
      case 0x94: count = data; break;
      case 0x84: id = data; break;
      case 0xA0: ++p.depth; break;
      case 0xC0: --p.depth; break;
      case 0x80: p.input[id] = 1 + size_bits * count / 8; break;
      case 0xB0: p.feature[id] = 1 + size_bits * count / 8; break;
      default: break;
    }
    i += 1 + n;
  }
  return p;
}

}  // namespace

TEST_GROUP(Descriptor){};

TEST(Descriptor, VendorPageAndBalancedCollections) {
  const Parsed p = parse();
  CHECK_TRUE(p.ok);
  CHECK_EQUAL(0xFF00u, p.usage_page);
  CHECK_EQUAL(0, p.depth);
}

TEST(Descriptor, ReportLengthsMatchTheCodec) {
  const Parsed p = parse();
  CHECK_EQUAL(kMeasurementSize, p.input[kReportMeasurement]);
  CHECK_EQUAL(kFeatureChunkSize, p.input[kReportFeatureChunk]);
  CHECK_EQUAL(kDeviceInfoSize, p.feature[kReportDeviceInfo]);
  CHECK_EQUAL(kConfigSize, p.feature[kReportConfig]);
  CHECK_EQUAL(kMailboxSize, p.feature[kReportMailbox]);
  CHECK_EQUAL(kLensChunkSize, p.feature[kReportLens]);
  size_t largest = 0;
  for (size_t id = 0; id < 256; ++id) largest = p.feature[id] > largest ? p.feature[id] : largest;
  CHECK_EQUAL(kMaxReportSize, largest);
}

TEST(Descriptor, NoInputReportIsOneFullSpeedPacketLong) {
  const Parsed p = parse();
  size_t largest = 0;
  for (size_t id = 0; id < 256; ++id) {
    CHECK_TRUE(p.input[id] != 64);
    if (p.input[id] > largest) largest = p.input[id];
  }
  CHECK_EQUAL(kMaxInputReportSize, largest);
  CHECK_TRUE(largest < 64);
}

TEST(Descriptor, PidCodesTestIds) {
  CHECK_EQUAL(0x1209, kUsbVendorId);
  CHECK_EQUAL(0x0001, kUsbProductId);
}
