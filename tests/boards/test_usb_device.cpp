// The blue pill's USB device logic replayed against the SETUP packets a Linux
// host sends when it enumerates an HID device and then uses hidapi's feature
// reports (as seen with usbmon), plus a parse of the descriptors the way the
// host's USB core and HID driver read them.
#include <CppUTest/TestHarness.h>

#include <cstdint>
#include <cstring>
#include <vector>

#include "lumavel/bluepill/usb_device.hpp"
#include "lumavel/protocol/descriptor.hpp"
#include "lumavel/protocol/device_config.hpp"
#include "lumavel/protocol/reports.hpp"

using lumavel::bluepill::ControlReply;
namespace protocol = lumavel::protocol;

namespace {

const uint8_t kUid[12] = {0x30, 0xFF, 0x6B, 0x06, 0x48, 0x4B, 0x38, 0x35, 0x12, 0x58, 0x11, 0x43};

std::vector<uint8_t> bytes(const ControlReply& r) {
  return r.kind == ControlReply::kData ? std::vector<uint8_t>(r.data, r.data + r.len) : std::vector<uint8_t>{};
}

struct Device {
  lumavel::bluepill::Descriptors d{};
  lumavel::bluepill::UsbControl ctl{d};
  Device() { lumavel::bluepill::build_descriptors(kUid, d); }
  ControlReply setup(std::vector<uint8_t> pkt) { return ctl.setup(pkt.data()); }
};

// A feature handler standing in for the app: answers 0x02, accepts a valid 0x03.
struct FakeApp {
  int gets = 0, sets = 0;
  std::vector<uint8_t> last_set;
  static size_t handle(void* ctx, uint8_t id, bool is_set, uint8_t* buf, size_t len, size_t cap) {
    auto* a = static_cast<FakeApp*>(ctx);
    if (is_set) {
      ++a->sets;
      a->last_set.assign(buf, buf + len);
      protocol::DeviceConfig c{};
      return id == protocol::kReportConfig && protocol::decode_config(buf, len, c).ok() ? 1 : 0;
    }
    ++a->gets;
    if (id != protocol::kReportDeviceInfo) return 0;
    protocol::DeviceInfo info{};
    std::strcpy(info.board, "test");
    info.width = 128;
    info.height = 1;
    info.max_columns = 128;
    info.max_rows = 1;
    info.max_kernels = 4;
    return protocol::encode_device_info(info, buf, cap);
  }
};

}  // namespace

TEST_GROUP(UsbDescriptors){};

TEST(UsbDescriptors, DeviceDescriptorNamesTheProtocolIds) {
  Device dev;
  const uint8_t* p = dev.d.device;
  CHECK_EQUAL(18, p[0]);
  CHECK_EQUAL(1, p[1]);
  CHECK_EQUAL(0x0200, p[2] | p[3] << 8);
  CHECK_EQUAL(64, p[7]);
  CHECK_EQUAL(protocol::kUsbVendorId, p[8] | p[9] << 8);
  CHECK_EQUAL(protocol::kUsbProductId, p[10] | p[11] << 8);
  CHECK_EQUAL(1, p[17]);
}

TEST(UsbDescriptors, ConfigurationParsesAsOneHidInterfaceWithAnInterruptIn) {
  Device dev;
  const uint8_t* p = dev.d.config;
  const int total = p[2] | p[3] << 8;
  CHECK_EQUAL(static_cast<int>(sizeof dev.d.config), total);
  int interfaces = 0, hid = 0, endpoints = 0;
  for (int off = 0; off < total;) {
    const int len = p[off];
    CHECK_TRUE(len >= 2 && off + len <= total);
    const uint8_t type = p[off + 1];
    if (type == 4) {
      ++interfaces;
      CHECK_EQUAL(3, p[off + 5]);  // HID class
      CHECK_EQUAL(1, p[off + 4]);  // one endpoint
    } else if (type == 0x21) {
      ++hid;
      CHECK_EQUAL(0x22, p[off + 6]);
      CHECK_EQUAL(static_cast<int>(protocol::kReportDescriptorSize), p[off + 7] | p[off + 8] << 8);
    } else if (type == 5) {
      ++endpoints;
      CHECK_EQUAL(0x81, p[off + 2]);
      CHECK_EQUAL(3, p[off + 3] & 3);  // interrupt
      CHECK_TRUE((p[off + 4] | p[off + 5] << 8) >= static_cast<int>(protocol::kMaxInputReportSize));
      CHECK_EQUAL(protocol::kFullSpeedIntervalMs, p[off + 6]);
    }
    off += len;
  }
  CHECK_EQUAL(1, interfaces);
  CHECK_EQUAL(1, hid);
  CHECK_EQUAL(1, endpoints);
}

TEST(UsbDescriptors, SerialNumberIsTheUniqueIdInHex) {
  Device dev;
  const auto r = bytes(dev.setup({0x80, 0x06, 0x03, 0x03, 0x09, 0x04, 0xFF, 0x00}));
  CHECK_EQUAL(50u, r.size());
  std::string s;
  for (size_t i = 2; i < r.size(); i += 2) s += static_cast<char>(r[i]);
  STRCMP_EQUAL("30FF6B06484B383512581143", s.c_str());
}

TEST_GROUP(UsbEnumeration){};

TEST(UsbEnumeration, LinuxEnumerationSequence) {
  Device dev;
  // 1. First device descriptor read, 64 bytes asked, 18 returned.
  auto r = dev.setup({0x80, 0x06, 0x00, 0x01, 0x00, 0x00, 0x40, 0x00});
  CHECK_EQUAL(ControlReply::kData, r.kind);
  CHECK_EQUAL(18, r.len);
  // 2. SET_ADDRESS 7: acknowledged, applied only after the status stage.
  r = dev.setup({0x00, 0x05, 0x07, 0x00, 0x00, 0x00, 0x00, 0x00});
  CHECK_EQUAL(ControlReply::kAck, r.kind);
  CHECK_EQUAL(7, dev.ctl.status_done());
  CHECK_EQUAL(-1, dev.ctl.status_done());
  // 3. Device descriptor again, configuration header, then the whole of it.
  CHECK_EQUAL(18, dev.setup({0x80, 0x06, 0x00, 0x01, 0x00, 0x00, 0x12, 0x00}).len);
  CHECK_EQUAL(9, dev.setup({0x80, 0x06, 0x00, 0x02, 0x00, 0x00, 0x09, 0x00}).len);
  CHECK_EQUAL(34, dev.setup({0x80, 0x06, 0x00, 0x02, 0x00, 0x00, 0xFF, 0x00}).len);
  // 4. Strings: languages, product, manufacturer, serial.
  const auto lang = bytes(dev.setup({0x80, 0x06, 0x00, 0x03, 0x00, 0x00, 0xFF, 0x00}));
  CHECK_TRUE((std::vector<uint8_t>{4, 3, 0x09, 0x04}) == lang);
  CHECK_EQUAL(ControlReply::kData, dev.setup({0x80, 0x06, 0x02, 0x03, 0x09, 0x04, 0xFF, 0x00}).kind);
  CHECK_EQUAL(ControlReply::kData, dev.setup({0x80, 0x06, 0x01, 0x03, 0x09, 0x04, 0xFF, 0x00}).kind);
  CHECK_EQUAL(ControlReply::kStall, dev.setup({0x80, 0x06, 0x07, 0x03, 0x09, 0x04, 0xFF, 0x00}).kind);
  // 5. SET_CONFIGURATION 1.
  CHECK_EQUAL(0, dev.ctl.configuration());
  CHECK_EQUAL(ControlReply::kAck, dev.setup({0x00, 0x09, 0x01, 0x00, 0x00, 0x00, 0x00, 0x00}).kind);
  CHECK_EQUAL(1, dev.ctl.configuration());
  // 6. usbhid: SET_IDLE 0, then the report descriptor (asked with 64 bytes to spare).
  CHECK_EQUAL(ControlReply::kAck, dev.setup({0x21, 0x0A, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00}).kind);
  const uint16_t ask = static_cast<uint16_t>(protocol::kReportDescriptorSize + 64);
  r = dev.setup({0x81, 0x06, 0x00, 0x22, 0x00, 0x00, static_cast<uint8_t>(ask), static_cast<uint8_t>(ask >> 8)});
  CHECK_EQUAL(ControlReply::kData, r.kind);
  CHECK_EQUAL(protocol::kReportDescriptorSize, r.len);
  MEMCMP_EQUAL(protocol::kReportDescriptor, r.data, protocol::kReportDescriptorSize);
  // 7. Unknown requests stall; a bus reset unconfigures.
  CHECK_EQUAL(ControlReply::kStall, dev.setup({0x40, 0x01, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00}).kind);
  dev.ctl.bus_reset();
  CHECK_EQUAL(0, dev.ctl.configuration());
}

TEST(UsbEnumeration, GetFeatureReportWaitsForTheApp) {
  Device dev;
  FakeApp app;
  // GET_REPORT, feature (3), ID 2, 36 bytes.
  const auto r = dev.setup({0xA1, 0x01, 0x02, 0x03, 0x00, 0x00, 0x24, 0x00});
  CHECK_EQUAL(ControlReply::kPending, r.kind);
  CHECK_TRUE(dev.ctl.pending());
  const auto done = dev.ctl.serve(&FakeApp::handle, &app);
  CHECK_EQUAL(ControlReply::kData, done.kind);
  CHECK_EQUAL(protocol::kDeviceInfoSize, done.len);
  protocol::DeviceInfo info{};
  CHECK_TRUE(protocol::decode_device_info(done.data, done.len, info).ok());
  STRCMP_EQUAL("test", info.board);
  CHECK_FALSE(dev.ctl.pending());
  // Input reports are not fetched through GET_REPORT.
  CHECK_EQUAL(ControlReply::kStall, dev.setup({0xA1, 0x01, 0x01, 0x01, 0x00, 0x00, 0x2A, 0x00}).kind);
}

TEST(UsbEnumeration, SetFeatureReportArrivesInTwoPacketsAndIsJudgedByTheApp) {
  Device dev;
  FakeApp app;
  uint8_t cfg[protocol::kConfigSize];
  CHECK_EQUAL(protocol::kConfigSize, protocol::encode_config(protocol::default_device_config(), cfg, sizeof cfg));
  // SET_REPORT, feature (3), ID 3, 102 bytes: a 64-byte and a 38-byte OUT packet.
  CHECK_EQUAL(ControlReply::kReceive, dev.setup({0x21, 0x09, 0x03, 0x03, 0x00, 0x00, 0x66, 0x00}).kind);
  CHECK_EQUAL(ControlReply::kReceive, dev.ctl.out_data(cfg, 64).kind);
  CHECK_EQUAL(ControlReply::kPending, dev.ctl.out_data(cfg + 64, 38).kind);
  CHECK_EQUAL(ControlReply::kAck, dev.ctl.serve(&FakeApp::handle, &app).kind);
  CHECK_EQUAL(1, app.sets);
  CHECK_TRUE(std::vector<uint8_t>(cfg, cfg + sizeof cfg) == app.last_set);
  // The same with a corrupt CRC: the app refuses, the status stage stalls.
  cfg[50] ^= 1;
  dev.setup({0x21, 0x09, 0x03, 0x03, 0x00, 0x00, 0x66, 0x00});
  dev.ctl.out_data(cfg, 64);
  dev.ctl.out_data(cfg + 64, 38);
  CHECK_EQUAL(ControlReply::kStall, dev.ctl.serve(&FakeApp::handle, &app).kind);
  // More data than announced stalls at once.
  dev.setup({0x21, 0x09, 0x03, 0x03, 0x00, 0x00, 0x10, 0x00});
  CHECK_EQUAL(ControlReply::kStall, dev.ctl.out_data(cfg, 64).kind);
  // A report ID in the data that differs from wValue's is refused.
  dev.setup({0x21, 0x09, 0x02, 0x03, 0x00, 0x00, 0x66, 0x00});
  dev.ctl.out_data(cfg, 64);
  dev.ctl.out_data(cfg + 64, 38);
  CHECK_EQUAL(ControlReply::kStall, dev.ctl.serve(&FakeApp::handle, &app).kind);
}
