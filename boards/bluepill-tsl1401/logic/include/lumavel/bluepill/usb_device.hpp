// The USB full-speed HID device of the board, independent of the USB
// peripheral: descriptors (built around the protocol's report descriptor)
// and the control-endpoint request logic. The STM32 driver (usb_hid.cpp)
// moves packets; everything decided here is tested on the host by replaying
// the setup packets a Linux host sends.
//
// Feature reports go through the app: a GET_REPORT/SET_REPORT is held
// pending (the peripheral NAKs the data or status stage) until the app's
// ReportLink::poll_features serves it, at most one frame later.
#pragma once
#include <cstddef>
#include <cstdint>

#include "lumavel/hal/report_link.hpp"
#include "lumavel/protocol/descriptor.hpp"

namespace lumavel::bluepill {

constexpr uint8_t kEp0Size = 64;
constexpr uint8_t kEpInAddress = 0x81;
constexpr uint8_t kEpInSize = 64;

struct Descriptors {
  uint8_t device[18];
  uint8_t config[34];  // configuration + interface + HID + endpoint
  uint8_t lang[4];
  uint8_t manufacturer[2 + 2 * 7];   // "lumavel"
  uint8_t product[2 + 2 * 16];       // "lumavel bluepill"
  uint8_t serial[2 + 2 * 24];        // the MCU's 96-bit unique ID in hex
};

// serial_id: the 12 bytes of the STM32 unique device ID.
void build_descriptors(const uint8_t serial_id[12], Descriptors& out);

struct ControlReply {
  enum Kind : uint8_t {
    kStall,      // refuse the request
    kData,       // send data (IN data stage), then expect the status OUT
    kAck,        // no data stage: send the zero-length status IN
    kReceive,    // OUT data stage follows (SET_REPORT)
    kPending,    // wait for the app (NAK) until serve() says
  };
  Kind kind;
  const uint8_t* data;
  uint16_t len;
};

class UsbControl {
 public:
  explicit UsbControl(const Descriptors& d) : d_(d) {}

  // A SETUP packet (8 bytes) arrived on endpoint 0.
  ControlReply setup(const uint8_t* pkt);
  // OUT data stage bytes of a SET_REPORT (in packet order).
  ControlReply out_data(const uint8_t* data, size_t len);
  // The status stage finished (applies SET_ADDRESS). Returns the address to
  // program into the peripheral now, or -1 when nothing changes.
  int status_done();
  // Answers a pending feature request through the app's handler.
  ControlReply serve(hal::ReportLink::FeatureHandler handler, void* ctx);
  bool pending() const { return pending_; }
  uint8_t configuration() const { return configuration_; }
  void bus_reset();

 private:
  ControlReply get_descriptor(uint8_t type, uint8_t index, uint16_t max_len);
  static ControlReply data(const uint8_t* p, size_t len, uint16_t max_len);

  const Descriptors& d_;
  uint8_t configuration_ = 0;
  int new_address_ = -1;
  bool pending_ = false;
  bool pending_set_ = false;
  uint8_t report_id_ = 0;
  uint16_t expect_ = 0;    // SET_REPORT bytes still to receive
  uint16_t received_ = 0;
  uint16_t max_len_ = 0;   // GET_REPORT wLength
  uint8_t small_[2]{};     // replies of GET_STATUS / GET_CONFIGURATION / GET_IDLE
  uint8_t idle_rate_ = 0;
  uint8_t buf_[protocol::kMaxReportSize]{};
};

}  // namespace lumavel::bluepill
