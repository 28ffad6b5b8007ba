#include "lumavel/protocol/descriptor.hpp"

namespace lumavel::protocol {

namespace {
// HID report counts exclude the report ID byte.
constexpr uint8_t count_of(size_t total) { return static_cast<uint8_t>(total - 1); }
static_assert(kMeasurementSize - 1 < 256 && kConfigSize - 1 < 256, "one-byte report counts");
static_assert(kLensChunkSize <= kFeatureChunkData, "a lens piece fits one mailbox chunk");
static_assert(kMaxInputReportSize != 64 && kMeasurementSize != 64 && kFeatureChunkSize != 64,
              "no 64-byte input reports (zero-length-packet pitfall)");
static_assert(kMaxInputReportSize < 64, "input reports fit one full-speed packet");
}  // namespace

const uint8_t kReportDescriptor[] = {
    0x06, 0x00, 0xFF,  // Usage Page (Vendor 0xFF00)
    0x09, 0x01,        // Usage (0x01)
    0xA1, 0x01,        // Collection (Application)
    0x15, 0x00,        //   Logical Minimum (0)
    0x26, 0xFF, 0x00,  //   Logical Maximum (255)
    0x75, 0x08,        //   Report Size (8)
    0x85, kReportMeasurement, 0x95, count_of(kMeasurementSize),
    0x09, 0x01, 0x81, 0x02,  // Input (Data,Var,Abs)
    0x85, kReportDeviceInfo, 0x95, count_of(kDeviceInfoSize),
    0x09, 0x02, 0xB1, 0x02,  // Feature (Data,Var,Abs)
    0x85, kReportConfig, 0x95, count_of(kConfigSize),
    0x09, 0x03, 0xB1, 0x02,  // Feature
    0x85, kReportMailbox, 0x95, count_of(kMailboxSize),
    0x09, 0x04, 0xB1, 0x02,  // Feature
    0x85, kReportLens, 0x95, count_of(kLensChunkSize),
    0x09, 0x06, 0xB1, 0x02,  // Feature
    0x85, kReportFeatureChunk, 0x95, count_of(kFeatureChunkSize),
    0x09, 0x05, 0x81, 0x02,  // Input
    0xC0,                    // End Collection
};
const size_t kReportDescriptorSize = sizeof(kReportDescriptor);

}  // namespace lumavel::protocol
