#include "lumavel/bluepill/usb_device.hpp"

namespace lumavel::bluepill {
namespace {

constexpr uint8_t kDescDevice = 1, kDescConfig = 2, kDescString = 3;
constexpr uint8_t kDescHid = 0x21, kDescReport = 0x22;
constexpr uint8_t kReqGetStatus = 0, kReqClearFeature = 1, kReqSetFeature = 3, kReqSetAddress = 5,
                  kReqGetDescriptor = 6, kReqGetConfiguration = 8, kReqSetConfiguration = 9,
                  kReqGetInterface = 10, kReqSetInterface = 11;
constexpr uint8_t kHidGetReport = 1, kHidGetIdle = 2, kHidGetProtocol = 3, kHidSetReport = 9,
                  kHidSetIdle = 0x0A, kHidSetProtocol = 0x0B;
constexpr uint8_t kReportTypeFeature = 3;

void put16(uint8_t* p, uint16_t v) {
  p[0] = static_cast<uint8_t>(v);
  p[1] = static_cast<uint8_t>(v >> 8);
}

template <size_t N>
void string_desc(uint8_t (&out)[N], const char* text) {
  out[0] = static_cast<uint8_t>(N);
  out[1] = kDescString;
  for (size_t i = 0; 2 + 2 * i < N; ++i) {
    out[2 + 2 * i] = static_cast<uint8_t>(text[i]);
    out[3 + 2 * i] = 0;
  }
}

}  // namespace

void build_descriptors(const uint8_t serial_id[12], Descriptors& d) {
  const uint8_t device[18] = {18, kDescDevice, 0x00, 0x02,  // USB 2.0
                              0, 0, 0,                     // class in the interface
                              kEp0Size, 0, 0, 0, 0,        // VID, PID below
                              0x00, 0x01,                  // device release 1.00
                              1, 2, 3,                     // strings
                              1};
  for (size_t i = 0; i < sizeof device; ++i) d.device[i] = device[i];
  put16(d.device + 8, protocol::kUsbVendorId);
  put16(d.device + 10, protocol::kUsbProductId);

  const uint8_t config[34] = {
      9, kDescConfig, 34, 0, 1, 1, 0, 0x80, 50,  // 1 interface, bus powered, 100 mA
      9, 4, 0, 0, 1, 3, 0, 0, 0,                  // interface 0: 1 endpoint, HID, no boot protocol
      9, kDescHid, 0x11, 0x01, 0, 1, kDescReport, 0, 0,  // HID 1.11, one report descriptor
      7, 5, kEpInAddress, 0x03, kEpInSize, 0, protocol::kFullSpeedIntervalMs};  // interrupt IN
  for (size_t i = 0; i < sizeof config; ++i) d.config[i] = config[i];
  put16(d.config + 25, static_cast<uint16_t>(protocol::kReportDescriptorSize));

  const uint8_t lang[4] = {4, kDescString, 0x09, 0x04};  // English (US)
  for (size_t i = 0; i < sizeof lang; ++i) d.lang[i] = lang[i];
  string_desc(d.manufacturer, "lumavel");
  string_desc(d.product, "lumavel bluepill");
  char hex[25];
  const char digits[] = "0123456789ABCDEF";
  for (int i = 0; i < 12; ++i) {
    hex[2 * i] = digits[serial_id[i] >> 4];
    hex[2 * i + 1] = digits[serial_id[i] & 15];
  }
  hex[24] = '\0';
  string_desc(d.serial, hex);
}

ControlReply UsbControl::data(const uint8_t* p, size_t len, uint16_t max_len) {
  return ControlReply{ControlReply::kData, p, static_cast<uint16_t>(len < max_len ? len : max_len)};
}

ControlReply UsbControl::get_descriptor(uint8_t type, uint8_t index, uint16_t max_len) {
  switch (type) {
    case kDescDevice: return data(d_.device, sizeof d_.device, max_len);
    case kDescConfig: return data(d_.config, sizeof d_.config, max_len);
    case kDescHid: return data(d_.config + 18, 9, max_len);
    case kDescReport: return data(protocol::kReportDescriptor, protocol::kReportDescriptorSize, max_len);
    case kDescString:
      switch (index) {
        case 0: return data(d_.lang, sizeof d_.lang, max_len);
        case 1: return data(d_.manufacturer, sizeof d_.manufacturer, max_len);
        case 2: return data(d_.product, sizeof d_.product, max_len);
        case 3: return data(d_.serial, sizeof d_.serial, max_len);
        default: break;
      }
      break;
    default: break;
  }
  return ControlReply{ControlReply::kStall, nullptr, 0};
}

void UsbControl::bus_reset() {
  configuration_ = 0;
  new_address_ = -1;
  pending_ = false;
  expect_ = 0;
}

ControlReply UsbControl::setup(const uint8_t* pkt) {
  const uint8_t type = pkt[0];
  const uint8_t req = pkt[1];
  const uint16_t value = static_cast<uint16_t>(pkt[2] | pkt[3] << 8);
  const uint16_t length = static_cast<uint16_t>(pkt[6] | pkt[7] << 8);
  const ControlReply stall{ControlReply::kStall, nullptr, 0};
  const ControlReply ack{ControlReply::kAck, nullptr, 0};
  pending_ = false;  // a new SETUP aborts whatever was in progress
  expect_ = 0;

  if ((type & 0x60) == 0) {  // standard
    switch (req) {
      case kReqGetDescriptor:
        if (type != 0x80 && type != 0x81) return stall;
        return get_descriptor(static_cast<uint8_t>(value >> 8), static_cast<uint8_t>(value), length);
      case kReqSetAddress:
        if (type != 0x00 || value > 127) return stall;
        new_address_ = value;  // takes effect after the status stage
        return ack;
      case kReqSetConfiguration:
        if (type != 0x00 || value > 1) return stall;
        configuration_ = static_cast<uint8_t>(value);
        return ack;
      case kReqGetConfiguration:
        small_[0] = configuration_;
        return data(small_, 1, length);
      case kReqGetStatus:
        small_[0] = small_[1] = 0;  // bus powered, no remote wake-up, endpoints not halted
        return data(small_, 2, length);
      case kReqGetInterface:
        small_[0] = 0;
        return data(small_, 1, length);
      case kReqClearFeature:
      case kReqSetFeature:
      case kReqSetInterface:
        return ack;
      default:
        return stall;
    }
  }
  if ((type & 0x60) == 0x20 && (type & 0x1F) == 1) {  // HID class, to the interface
    const uint8_t report_type = static_cast<uint8_t>(value >> 8);
    switch (req) {
      case kHidGetReport:
        if (report_type != kReportTypeFeature) return stall;
        report_id_ = static_cast<uint8_t>(value);
        max_len_ = length;
        pending_ = true;
        pending_set_ = false;
        return ControlReply{ControlReply::kPending, nullptr, 0};
      case kHidSetReport:
        if (report_type != kReportTypeFeature || length == 0 || length > sizeof buf_) return stall;
        report_id_ = static_cast<uint8_t>(value);
        expect_ = length;
        received_ = 0;
        return ControlReply{ControlReply::kReceive, nullptr, 0};
      case kHidSetIdle:
        idle_rate_ = static_cast<uint8_t>(value >> 8);
        return ack;
      case kHidGetIdle:
        small_[0] = idle_rate_;
        return data(small_, 1, length);
      case kHidSetProtocol:
        return ack;
      case kHidGetProtocol:
        small_[0] = 1;  // report protocol
        return data(small_, 1, length);
      default:
        return stall;
    }
  }
  return stall;
}

ControlReply UsbControl::out_data(const uint8_t* bytes, size_t len) {
  if (expect_ == 0 || received_ + len > expect_) {
    expect_ = 0;
    return ControlReply{ControlReply::kStall, nullptr, 0};
  }
  for (size_t i = 0; i < len; ++i) buf_[received_ + i] = bytes[i];
  received_ = static_cast<uint16_t>(received_ + len);
  if (received_ < expect_) return ControlReply{ControlReply::kReceive, nullptr, 0};
  expect_ = 0;
  pending_ = true;
  pending_set_ = true;
  return ControlReply{ControlReply::kPending, nullptr, 0};
}

int UsbControl::status_done() {
  const int a = new_address_;
  new_address_ = -1;
  return a;
}

ControlReply UsbControl::serve(hal::ReportLink::FeatureHandler handler, void* ctx) {
  if (!pending_) return ControlReply{ControlReply::kPending, nullptr, 0};
  pending_ = false;
  if (pending_set_) {
    // With numbered reports the data stage starts with the report ID.
    if (received_ == 0 || buf_[0] != report_id_) return ControlReply{ControlReply::kStall, nullptr, 0};
    const size_t ok = handler(ctx, report_id_, true, buf_, received_, sizeof buf_);
    return ControlReply{ok != 0 ? ControlReply::kAck : ControlReply::kStall, nullptr, 0};
  }
  const size_t n = handler(ctx, report_id_, false, buf_, 0, sizeof buf_);
  if (n == 0 || n > sizeof buf_) return ControlReply{ControlReply::kStall, nullptr, 0};
  return data(buf_, n, max_len_);
}

}  // namespace lumavel::bluepill
