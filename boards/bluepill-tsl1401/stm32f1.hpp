// The STM32F103 registers this board uses (RM0008), no vendor headers.
#pragma once
#include <cstdint>

namespace stm32 {

inline volatile uint32_t& reg(uint32_t addr) { return *reinterpret_cast<volatile uint32_t*>(addr); }

namespace rcc {
constexpr uint32_t kBase = 0x40021000u;
inline volatile uint32_t& cr() { return reg(kBase + 0x00); }
inline volatile uint32_t& cfgr() { return reg(kBase + 0x04); }
inline volatile uint32_t& apb2enr() { return reg(kBase + 0x18); }
inline volatile uint32_t& apb1enr() { return reg(kBase + 0x1C); }
inline volatile uint32_t& csr() { return reg(kBase + 0x24); }
}  // namespace rcc

namespace flash {
constexpr uint32_t kBase = 0x40022000u;
inline volatile uint32_t& acr() { return reg(kBase + 0x00); }
inline volatile uint32_t& keyr() { return reg(kBase + 0x04); }
inline volatile uint32_t& sr() { return reg(kBase + 0x0C); }
inline volatile uint32_t& cr() { return reg(kBase + 0x10); }
inline volatile uint32_t& ar() { return reg(kBase + 0x14); }
}  // namespace flash

struct Gpio {
  uint32_t base;
  volatile uint32_t& crl() const { return reg(base + 0x00); }
  volatile uint32_t& crh() const { return reg(base + 0x04); }
  volatile uint32_t& idr() const { return reg(base + 0x08); }
  volatile uint32_t& bsrr() const { return reg(base + 0x10); }
  // Sets the 4-bit MODE/CNF field of one pin.
  void mode(int pin, uint32_t cnf_mode) const {
    volatile uint32_t& r = pin < 8 ? crl() : crh();
    const int shift = (pin & 7) * 4;
    r = (r & ~(0xFu << shift)) | (cnf_mode << shift);
  }
  void set(int pin) const { bsrr() = 1u << pin; }
  void clear(int pin) const { bsrr() = 1u << (pin + 16); }
};
constexpr Gpio kGpioA{0x40010800u};
constexpr Gpio kGpioB{0x40010C00u};
constexpr Gpio kGpioC{0x40011000u};
constexpr uint32_t kAnalog = 0x0;           // input, analog
constexpr uint32_t kInputFloating = 0x4;
constexpr uint32_t kOutPushPull50 = 0x3;
constexpr uint32_t kOutPushPull2 = 0x2;
constexpr uint32_t kAltOpenDrain50 = 0xF;

namespace adc1 {
constexpr uint32_t kBase = 0x40012400u;
inline volatile uint32_t& sr() { return reg(kBase + 0x00); }
inline volatile uint32_t& cr2() { return reg(kBase + 0x08); }
inline volatile uint32_t& smpr2() { return reg(kBase + 0x10); }
inline volatile uint32_t& sqr1() { return reg(kBase + 0x2C); }
inline volatile uint32_t& sqr3() { return reg(kBase + 0x34); }
inline volatile uint32_t& dr() { return reg(kBase + 0x4C); }
}  // namespace adc1

namespace i2c1 {
constexpr uint32_t kBase = 0x40005400u;
inline volatile uint32_t& cr1() { return reg(kBase + 0x00); }
inline volatile uint32_t& cr2() { return reg(kBase + 0x04); }
inline volatile uint32_t& dr() { return reg(kBase + 0x10); }
inline volatile uint32_t& sr1() { return reg(kBase + 0x14); }
inline volatile uint32_t& sr2() { return reg(kBase + 0x18); }
inline volatile uint32_t& ccr() { return reg(kBase + 0x1C); }
inline volatile uint32_t& trise() { return reg(kBase + 0x20); }
}  // namespace i2c1

namespace usb {
constexpr uint32_t kBase = 0x40005C00u;
constexpr uint32_t kPma = 0x40006000u;  // 512 bytes, 16-bit words at 32-bit spacing
inline volatile uint32_t& epr(int n) { return reg(kBase + 4u * static_cast<uint32_t>(n)); }
inline volatile uint32_t& cntr() { return reg(kBase + 0x40); }
inline volatile uint32_t& istr() { return reg(kBase + 0x44); }
inline volatile uint32_t& daddr() { return reg(kBase + 0x4C); }
inline volatile uint32_t& btable() { return reg(kBase + 0x50); }
// PMA half-word at USB-local byte address a (even).
inline volatile uint32_t& pma(uint32_t a) { return reg(kPma + a * 2u); }
}  // namespace usb

namespace iwdg {
constexpr uint32_t kBase = 0x40003000u;
inline volatile uint32_t& kr() { return reg(kBase + 0x00); }
inline volatile uint32_t& pr() { return reg(kBase + 0x04); }
inline volatile uint32_t& rlr() { return reg(kBase + 0x08); }
inline volatile uint32_t& sr() { return reg(kBase + 0x0C); }
}  // namespace iwdg

namespace systick {
inline volatile uint32_t& csr() { return reg(0xE000E010u); }
inline volatile uint32_t& rvr() { return reg(0xE000E014u); }
inline volatile uint32_t& cvr() { return reg(0xE000E018u); }
}  // namespace systick

constexpr uint32_t kUniqueId = 0x1FFFF7E8u;  // 96-bit device ID

}  // namespace stm32
