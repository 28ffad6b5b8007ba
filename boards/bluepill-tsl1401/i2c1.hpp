// I2C1 master, 400 kHz, polled, on PB6 (SCL) / PB7 (SDA). Every wait has a
// time-out so that a missing or stuck gyro cannot hang the frame loop.
#pragma once
#include <cstddef>
#include <cstdint>

#include "lumavel/bluepill/mpu6050.hpp"
#include "system.hpp"

namespace bluepill {

class I2c1 final : public lumavel::bluepill::I2cBus {
 public:
  explicit I2c1(SysTickClock& clock) : clock_(clock) {}
  void init();
  bool write_reg(uint8_t addr7, uint8_t reg, uint8_t value) override;
  bool read_regs(uint8_t addr7, uint8_t reg, uint8_t* buf, size_t len) override;
  void delay_ms(uint32_t ms) override { clock_.delay_ms(ms); }

 private:
  bool start_and_address(uint8_t byte);
  bool fail();
  SysTickClock& clock_;
};

}  // namespace bluepill
