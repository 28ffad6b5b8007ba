#include "usb_hid.hpp"

#include "stm32f1.hpp"

namespace bluepill {
namespace {

using namespace stm32;
using lumavel::bluepill::ControlReply;

// Packet memory (USB-local byte addresses): buffer table, then the buffers.
constexpr uint32_t kEp0Tx = 0x40, kEp0Rx = 0x80, kEp1Tx = 0xC0;
constexpr uint16_t kRx64 = 0x8400;  // COUNT_RX: 32-byte blocks, 2 blocks = 64 bytes

// EPnR bits: CTR_RX/CTR_TX clear on writing 0; DTOG/STAT toggle on writing 1;
// EP_TYPE, EP_KIND and EA are plain read/write.
constexpr uint32_t kCtrRx = 0x8000, kSetup = 0x0800, kCtrTx = 0x0080, kRw = 0x070F;
constexpr uint32_t kStall = 1, kNak = 2, kValid = 3;
constexpr uint32_t kIstrCtr = 0x8000, kIstrReset = 0x0400, kIstrSusp = 0x0800, kIstrWkup = 0x1000;

void btable(int ep, uint32_t field, uint16_t v) { usb::pma(static_cast<uint32_t>(ep) * 8u + field) = v; }
uint16_t rx_count(int ep) { return static_cast<uint16_t>(usb::pma(static_cast<uint32_t>(ep) * 8u + 6u) & 0x3FFu); }

void set_tx(int ep, uint32_t stat) {
  const uint32_t v = usb::epr(ep);
  usb::epr(ep) = (v & kRw) | kCtrRx | kCtrTx | ((v ^ (stat << 4)) & 0x0030u);
}
void set_rx(int ep, uint32_t stat) {
  const uint32_t v = usb::epr(ep);
  usb::epr(ep) = (v & kRw) | kCtrRx | kCtrTx | ((v ^ (stat << 12)) & 0x3000u);
}
void clear_ctr_rx(int ep) { usb::epr(ep) = (usb::epr(ep) & kRw) | kCtrTx; }
void clear_ctr_tx(int ep) { usb::epr(ep) = (usb::epr(ep) & kRw) | kCtrRx; }

void write_pma(uint32_t addr, const uint8_t* p, size_t n) {
  for (size_t i = 0; i < n; i += 2) {
    const uint32_t hi = i + 1 < n ? p[i + 1] : 0u;
    usb::pma(addr + static_cast<uint32_t>(i)) = p[i] | hi << 8;
  }
}
void read_pma(uint32_t addr, uint8_t* p, size_t n) {
  for (size_t i = 0; i < n; i += 2) {
    const uint32_t v = usb::pma(addr + static_cast<uint32_t>(i));
    p[i] = static_cast<uint8_t>(v);
    if (i + 1 < n) p[i + 1] = static_cast<uint8_t>(v >> 8);
  }
}

}  // namespace

void UsbHid::init(SysTickClock& clock) {
  rcc::apb2enr() |= 1u << 2;  // GPIOA
  kGpioA.mode(12, kOutPushPull2);
  kGpioA.clear(12);  // D+ low: the host sees a disconnect
  clock.delay_ms(10);
  kGpioA.mode(12, kInputFloating);
  rcc::apb1enr() |= 1u << 23;  // USB
  usb::cntr() = 1u;            // leave power-down, keep reset (FRES)
  clock.delay_ms(1);           // tSTARTUP
  usb::cntr() = 0;
  usb::istr() = 0;
  usb::btable() = 0;
  bus_reset();
}

void UsbHid::bus_reset() {
  btable(0, 0, kEp0Tx);
  btable(0, 2, 0);
  btable(0, 4, kEp0Rx);
  btable(0, 6, kRx64);
  btable(1, 0, kEp1Tx);
  btable(1, 2, 0);
  usb::epr(0) = 0x0200u;  // control, address 0 (STAT bits read 0 after reset: DISABLED)
  set_rx(0, kValid);
  set_tx(0, kNak);
  usb::epr(1) = 0x0600u | 1u;  // interrupt, address 1
  set_tx(1, kNak);
  usb::daddr() = 0x80u;  // enable function, address 0
  control_.bus_reset();
  tx_left_ = 0;
  status_in_ = false;
  in_busy_ = false;
}

void UsbHid::send_chunk() {
  const uint16_t n = tx_left_ < lumavel::bluepill::kEp0Size ? tx_left_ : lumavel::bluepill::kEp0Size;
  write_pma(kEp0Tx, tx_, n);
  btable(0, 2, n);
  tx_ += n;
  tx_left_ = static_cast<uint16_t>(tx_left_ - n);
  set_tx(0, kValid);
}

void UsbHid::apply(const ControlReply& r) {
  switch (r.kind) {
    case ControlReply::kStall:
      set_tx(0, kStall);
      set_rx(0, kStall);  // SETUP packets are still received while stalled
      break;
    case ControlReply::kData:
      tx_ = r.data;
      tx_left_ = r.len;
      // A short transfer that is a multiple of 64 ends with a zero-length packet.
      tx_zlp_ = r.len < w_length_ && r.len % lumavel::bluepill::kEp0Size == 0;
      status_in_ = false;
      send_chunk();
      set_rx(0, kValid);  // the host's status OUT (or an early one) is accepted
      break;
    case ControlReply::kAck:
      btable(0, 2, 0);
      status_in_ = true;
      set_tx(0, kValid);
      break;
    case ControlReply::kReceive:
      set_rx(0, kValid);
      break;
    case ControlReply::kPending:
      set_tx(0, kNak);  // the data or status stage waits for the app
      break;
  }
}

void UsbHid::ep0() {
  const uint32_t v = usb::epr(0);
  if ((v & kCtrRx) != 0) {
    uint8_t pkt[lumavel::bluepill::kEp0Size];
    const uint16_t n = rx_count(0);
    read_pma(kEp0Rx, pkt, n > sizeof pkt ? sizeof pkt : n);
    clear_ctr_rx(0);
    if ((v & kSetup) != 0 && n == 8) {
      w_length_ = static_cast<uint16_t>(pkt[6] | pkt[7] << 8);
      tx_left_ = 0;
      apply(control_.setup(pkt));
    } else if (control_.pending() || n == 0) {
      set_rx(0, kValid);  // status OUT of an IN transfer
    } else {
      apply(control_.out_data(pkt, n));
    }
  }
  if ((v & kCtrTx) != 0) {
    clear_ctr_tx(0);
    if (status_in_) {
      status_in_ = false;
      const int a = control_.status_done();
      if (a >= 0) usb::daddr() = 0x80u | static_cast<uint32_t>(a);
    } else if (tx_left_ > 0) {
      send_chunk();
    } else if (tx_zlp_) {
      tx_zlp_ = false;
      btable(0, 2, 0);
      set_tx(0, kValid);
    }
  }
}

void UsbHid::poll() {
  for (int guard = 0; guard < 8; ++guard) {
    const uint32_t istr = usb::istr();
    if ((istr & kIstrReset) != 0) {
      usb::istr() = ~kIstrReset & 0xFFFFu;
      bus_reset();
      continue;
    }
    if ((istr & (kIstrSusp | kIstrWkup)) != 0) {
      usb::istr() = ~(kIstrSusp | kIstrWkup) & 0xFFFFu;  // suspend is not handled (see README)
    }
    if ((istr & kIstrCtr) == 0) return;
    const int ep = static_cast<int>(istr & 0xFu);
    if (ep == 0) {
      ep0();
    } else if (ep == 1 && (usb::epr(1) & kCtrTx) != 0) {
      clear_ctr_tx(1);
      in_busy_ = false;
    } else {
      usb::epr(ep) = usb::epr(ep) & kRw;  // unexpected endpoint: clear both CTR flags
    }
  }
}

bool UsbHid::send_input(const uint8_t* report, size_t len) {
  poll();
  if (!configured() || in_busy_ || len > lumavel::bluepill::kEpInSize) return false;
  write_pma(kEp1Tx, report, len);
  btable(1, 2, static_cast<uint16_t>(len));
  set_tx(1, kValid);
  in_busy_ = true;
  return true;
}

void UsbHid::poll_features(FeatureHandler handler, void* ctx) {
  poll();
  if (control_.pending()) apply(control_.serve(handler, ctx));
}

}  // namespace bluepill
