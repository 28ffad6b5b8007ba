// InvenSense MPU-6050 yaw gyro over I2C (register map rev 4.2): set-up for a
// 500 Hz z-gyro stream through the on-chip FIFO, and FIFO read-out into
// time-stamped RateQ24 samples. Bus access goes through I2cBus so that the
// register set-up is tested on the host against the recorded transactions.
#pragma once
#include <cstddef>
#include <cstdint>

#include "lumavel/core/fixed.hpp"
#include "lumavel/hal/gyro.hpp"

namespace lumavel::bluepill {

class I2cBus {
 public:
  virtual bool write_reg(uint8_t addr7, uint8_t reg, uint8_t value) = 0;
  virtual bool read_regs(uint8_t addr7, uint8_t reg, uint8_t* buf, size_t len) = 0;
  virtual void delay_ms(uint32_t ms) = 0;

 protected:
  ~I2cBus() = default;
};

namespace mpu {
constexpr uint8_t kAddress = 0x68;  // AD0 low
constexpr uint8_t kSmplrtDiv = 0x19;
constexpr uint8_t kConfig = 0x1A;
constexpr uint8_t kGyroConfig = 0x1B;
constexpr uint8_t kFifoEn = 0x23;
constexpr uint8_t kUserCtrl = 0x6A;
constexpr uint8_t kPwrMgmt1 = 0x6B;
constexpr uint8_t kFifoCountH = 0x72;
constexpr uint8_t kFifoRW = 0x74;
constexpr uint8_t kWhoAmI = 0x75;
constexpr uint8_t kWhoAmIValue = 0x68;
constexpr uint32_t kSamplePeriodNs = 2000000;  // 1 kHz gyro rate (DLPF on) / (1 + 1)
constexpr uint16_t kFifoSize = 1024;
}  // namespace mpu

// Raw z-gyro count at +-500 deg/s full scale (65.5 LSB per deg/s) to rad/s Q7.24:
// 2^24 * pi / 180 / 65.5 = 4470.499 per count.
RateQ24 mpu6050_rate_q24(int16_t raw);

class Mpu6050 {
 public:
  // Resets the chip and sets up: PLL clock, DLPF 44 Hz, 500 Hz, +-500 deg/s,
  // z-gyro only into the FIFO. False if it does not answer as an MPU-6050.
  bool init(I2cBus& bus);
  // Moves the FIFO's samples into `out` (up to cap), time-stamped backwards
  // from now_ns at the sample period; the newest is taken to be at now_ns.
  // Returns the count; an overflowed FIFO is reset and counted.
  size_t poll(I2cBus& bus, uint64_t now_ns, hal::GyroSample* out, size_t cap);
  uint32_t overflows() const { return overflows_; }

 private:
  bool reset_fifo(I2cBus& bus);
  uint64_t last_t_ns_ = 0;
  uint32_t overflows_ = 0;
};

}  // namespace lumavel::bluepill
