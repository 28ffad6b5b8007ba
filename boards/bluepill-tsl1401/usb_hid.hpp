// The STM32F103 USB full-speed peripheral as the board's ReportLink: endpoint 0
// (control, 64 bytes) and interrupt IN endpoint 1 (64 bytes). Polled from the
// frame loop and while the camera waits; the request logic is UsbControl.
// PA11/PA12 (D-/D+); the blue pill's fixed 1.5 kOhm pull-up on D+ (R10) is
// overridden by driving PA12 low for 10 ms at start so that the host re-enumerates.
#pragma once
#include <cstddef>
#include <cstdint>

#include "lumavel/bluepill/usb_device.hpp"
#include "lumavel/hal/report_link.hpp"
#include "system.hpp"

namespace bluepill {

class UsbHid final : public lumavel::hal::ReportLink {
 public:
  explicit UsbHid(const lumavel::bluepill::Descriptors& d) : control_(d) {}
  void init(SysTickClock& clock);
  // Services the peripheral: resets, SETUP/OUT/IN completions.
  void poll();
  bool send_input(const uint8_t* report, size_t len) override;
  void poll_features(FeatureHandler handler, void* ctx) override;
  bool configured() const { return control_.configuration() != 0; }

 private:
  void bus_reset();
  void apply(const lumavel::bluepill::ControlReply& r);
  void send_chunk();
  void ep0();

  lumavel::bluepill::UsbControl control_;
  const uint8_t* tx_ = nullptr;  // control IN data still to send
  uint16_t tx_left_ = 0;
  bool tx_zlp_ = false;          // end the data stage with a zero-length packet
  bool status_in_ = false;       // the IN being sent is the status stage
  uint16_t w_length_ = 0;
  bool in_busy_ = false;
};

}  // namespace bluepill
