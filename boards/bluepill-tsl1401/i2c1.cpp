#include "i2c1.hpp"

#include "clock_tree.hpp"
#include "stm32f1.hpp"

namespace bluepill {
namespace {

using namespace stm32;
constexpr uint32_t kSB = 1u << 0, kADDR = 1u << 1, kBTF = 1u << 2, kRXNE = 1u << 6, kTXE = 1u << 7,
                   kAF = 1u << 10;
constexpr uint32_t kPE = 1u << 0, kSTART = 1u << 8, kSTOP = 1u << 9, kACK = 1u << 10, kSWRST = 1u << 15;

// Waits for a status bit of SR1; false on NACK or after ~1 ms of polling.
bool wait_sr1(uint32_t bit) {
  for (uint32_t i = 0; i < 20000; ++i) {
    const uint32_t sr = i2c1::sr1();
    if ((sr & kAF) != 0) return false;
    if ((sr & bit) != 0) return true;
  }
  return false;
}

// Reading SR2 after SR1 clears ADDR (the read itself is the point).
void clear_addr() {
  const uint32_t sr2 = i2c1::sr2();
  static_cast<void>(sr2);
}

}  // namespace

void I2c1::init() {
  rcc::apb2enr() |= (1u << 3) | (1u << 0);  // GPIOB, AFIO
  rcc::apb1enr() |= 1u << 21;               // I2C1
  kGpioB.mode(6, kAltOpenDrain50);
  kGpioB.mode(7, kAltOpenDrain50);
  i2c1::cr1() = kSWRST;
  i2c1::cr1() = 0;
  i2c1::cr2() = kApb1Hz / 1000000u;  // FREQ = 36
  i2c1::ccr() = (1u << 15) | 30u;    // fast mode, Tlow/Thigh = 2: 36 MHz / (3 * 30) = 400 kHz
  i2c1::trise() = kApb1Hz / 1000000u * 300u / 1000u + 1u;  // 300 ns rise time
  i2c1::cr1() = kPE;
}

bool I2c1::fail() {
  i2c1::cr1() |= kSTOP;
  i2c1::sr1() = 0;  // clear AF
  return false;
}

bool I2c1::start_and_address(uint8_t byte) {
  i2c1::cr1() |= kSTART;
  if (!wait_sr1(kSB)) return false;
  i2c1::dr() = byte;
  if (!wait_sr1(kADDR)) return false;
  return true;
}

bool I2c1::write_reg(uint8_t addr7, uint8_t reg, uint8_t value) {
  if (!start_and_address(static_cast<uint8_t>(addr7 << 1))) return fail();
  clear_addr();
  i2c1::dr() = reg;
  if (!wait_sr1(kTXE)) return fail();
  i2c1::dr() = value;
  if (!wait_sr1(kBTF)) return fail();
  i2c1::cr1() |= kSTOP;
  return true;
}

bool I2c1::read_regs(uint8_t addr7, uint8_t reg, uint8_t* buf, size_t len) {
  if (len == 0) return true;
  if (!start_and_address(static_cast<uint8_t>(addr7 << 1))) return fail();
  clear_addr();
  i2c1::dr() = reg;
  if (!wait_sr1(kBTF)) return fail();
  if (!start_and_address(static_cast<uint8_t>(addr7 << 1 | 1))) return fail();  // repeated start
  if (len == 1) {
    i2c1::cr1() &= ~kACK;  // NACK the only byte: before ADDR is cleared
    clear_addr();
    i2c1::cr1() |= kSTOP;
    if (!wait_sr1(kRXNE)) return fail();
    buf[0] = static_cast<uint8_t>(i2c1::dr());
    return true;
  }
  i2c1::cr1() |= kACK;
  clear_addr();
  for (size_t i = 0; i < len; ++i) {
    if (!wait_sr1(kRXNE)) return fail();
    // While byte n-1 is still shifting in, arrange its NACK and the STOP after it.
    if (i + 2 == len) {
      i2c1::cr1() &= ~kACK;
      i2c1::cr1() |= kSTOP;
    }
    buf[i] = static_cast<uint8_t>(i2c1::dr());
  }
  return true;
}

}  // namespace bluepill
