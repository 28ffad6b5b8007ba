// USB identity and the HID report descriptor of a lumavel device.
// One vendor-defined collection (usage page 0xFF00): every report is opaque
// bytes to the OS; the layouts are in reports.hpp and device_config.hpp.
#pragma once
#include <cstddef>
#include <cstdint>

namespace lumavel::protocol {

// pid.codes test VID/PID until a PID is allocated.
constexpr uint16_t kUsbVendorId = 0x1209;
constexpr uint16_t kUsbProductId = 0x0001;
constexpr uint16_t kUsagePage = 0xFF00;
constexpr uint16_t kUsage = 0x0001;

// Protocol version carried in byte 1 of every report. 3: status bit 8 (no
// stereo), tagged mailbox answers, lens uploads staged apart from the tables
// in force (device info bytes 32, 33). 4: status bit 10 (V against the
// images' direction of travel).
constexpr uint8_t kProtocolVersion = 4;

// Report IDs. Byte 0 of every report is its ID.
enum ReportId : uint8_t {
  kReportMeasurement = 0x01,  // input: one per frame
  kReportDeviceInfo = 0x02,   // feature, get only
  kReportConfig = 0x03,       // feature, get and set
  kReportMailbox = 0x04,      // feature, set only: "send feature report N as input chunks"
  kReportLens = 0x05,         // feature, get and set: a piece of a lens table (lens.hpp)
  kReportFeatureChunk = 0x84, // input: a piece of a feature report sent through the mailbox
};

// Total lengths in bytes, report ID included. No input report is 64 bytes
// long: a full-speed packet of exactly 64 is followed by a zero-length packet
// on some stacks (Linux gadget HID), which hidapi-libusb returns as a read of 0.
constexpr size_t kMeasurementSize = 42;
constexpr size_t kDeviceInfoSize = 36;
constexpr size_t kConfigSize = 102;
constexpr size_t kMailboxSize = 4;
constexpr size_t kLensChunkSize = 55;
constexpr size_t kFeatureChunkSize = 62;
constexpr size_t kFeatureChunkData = 55;    // payload bytes per chunk
constexpr size_t kMaxInputReportSize = 62;  // largest input report (endpoint size)
constexpr size_t kMaxReportSize = 102;      // largest report of any kind

// Interrupt IN polling interval at full speed: one report per frame up to 1 kHz.
constexpr uint8_t kFullSpeedIntervalMs = 1;

extern const uint8_t kReportDescriptor[];
extern const size_t kReportDescriptorSize;

}  // namespace lumavel::protocol
