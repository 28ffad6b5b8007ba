#include "line_scan_adc.hpp"

#include "stm32f1.hpp"

namespace bluepill {
namespace {

constexpr int kSiPin = 4;
constexpr int kClkPin = 5;

uint16_t convert(uint32_t channel) {
  stm32::adc1::sqr3() = channel;
  stm32::adc1::cr2() |= 1u << 22;  // SWSTART
  while ((stm32::adc1::sr() & (1u << 1)) == 0) {  // EOC (20 ADC cycles = 1.7 us)
  }
  return static_cast<uint16_t>(stm32::adc1::dr() & 0xFFFu);
}

}  // namespace

void LineScanAdc::init() {
  using namespace stm32;
  rcc::apb2enr() |= (1u << 2) | (1u << 9);  // GPIOA, ADC1
  kGpioA.mode(0, kAnalog);
  kGpioA.mode(1, kAnalog);
  kGpioA.mode(kSiPin, kOutPushPull50);
  kGpioA.mode(kClkPin, kOutPushPull50);
  kGpioA.clear(kSiPin);
  kGpioA.clear(kClkPin);
  adc1::smpr2() = (1u << 0) | (1u << 3);       // channels 0, 1: 7.5-cycle sampling
  adc1::sqr1() = 0;                            // one conversion per start
  adc1::cr2() = (0x7u << 17) | (1u << 20) | 1u;  // software trigger, ADON (wake up)
  for (volatile int i = 0; i < 100; ++i) {      // tSTAB 1 us
  }
  adc1::cr2() |= 1u << 3;  // RSTCAL
  while ((adc1::cr2() & (1u << 3)) != 0) {
  }
  adc1::cr2() |= 1u << 2;  // CAL
  while ((adc1::cr2() & (1u << 2)) != 0) {
  }
}

void LineScanAdc::si(bool high) { high ? stm32::kGpioA.set(kSiPin) : stm32::kGpioA.clear(kSiPin); }
void LineScanAdc::clk(bool high) { high ? stm32::kGpioA.set(kClkPin) : stm32::kGpioA.clear(kClkPin); }

void LineScanAdc::settle() {
  // 12 cycles at 72 MHz = 167 ns > the 120 ns AO settling time.
  __asm__ volatile("nop\n nop\n nop\n nop\n nop\n nop\n nop\n nop\n nop\n nop\n nop\n nop");
}

void LineScanAdc::read_pair(uint16_t& ao0, uint16_t& ao1) {
  ao0 = convert(0);
  ao1 = convert(1);
}

}  // namespace bluepill
