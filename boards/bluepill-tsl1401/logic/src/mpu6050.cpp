#include "lumavel/bluepill/mpu6050.hpp"

namespace lumavel::bluepill {

RateQ24 mpu6050_rate_q24(int16_t raw) {
  // 4470.499 = 572224 / 128 (error 3e-7 relative); 32768 * 572224 > 2^31: 64-bit product.
  return static_cast<RateQ24>(fx::shr_round(int64_t{raw} * 572224, 7));
}

bool Mpu6050::reset_fifo(I2cBus& bus) {
  // FIFO_RESET clears it; FIFO_EN keeps it running.
  return bus.write_reg(mpu::kAddress, mpu::kUserCtrl, 0x04) &&
         bus.write_reg(mpu::kAddress, mpu::kUserCtrl, 0x40);
}

bool Mpu6050::init(I2cBus& bus) {
  uint8_t who = 0;
  if (!bus.read_regs(mpu::kAddress, mpu::kWhoAmI, &who, 1) || who != mpu::kWhoAmIValue) return false;
  if (!bus.write_reg(mpu::kAddress, mpu::kPwrMgmt1, 0x80)) return false;  // DEVICE_RESET
  bus.delay_ms(100);
  const bool ok = bus.write_reg(mpu::kAddress, mpu::kPwrMgmt1, 0x01) &&     // wake, PLL on X gyro
                  bus.write_reg(mpu::kAddress, mpu::kConfig, 0x03) &&       // DLPF 44 Hz: gyro at 1 kHz
                  bus.write_reg(mpu::kAddress, mpu::kSmplrtDiv, 0x01) &&    // 1 kHz / 2 = 500 Hz
                  bus.write_reg(mpu::kAddress, mpu::kGyroConfig, 0x08) &&   // +-500 deg/s
                  bus.write_reg(mpu::kAddress, mpu::kFifoEn, 0x10) &&       // ZG_FIFO_EN only
                  reset_fifo(bus);
  last_t_ns_ = 0;
  return ok;
}

size_t Mpu6050::poll(I2cBus& bus, uint64_t now_ns, hal::GyroSample* out, size_t cap) {
  uint8_t c[2];
  if (!bus.read_regs(mpu::kAddress, mpu::kFifoCountH, c, 2)) return 0;
  const uint16_t bytes = static_cast<uint16_t>(c[0] << 8 | c[1]);
  if (bytes >= mpu::kFifoSize) {  // overflowed: samples lost, order unknown
    ++overflows_;
    reset_fifo(bus);
    return 0;
  }
  size_t n = bytes / 2;
  if (n > cap) n = cap;
  // Burst reads of FIFO_R_W return consecutive FIFO bytes (big-endian samples).
  constexpr size_t kBurst = 16;
  for (size_t i = 0; i < n; i += kBurst) {
    const size_t m = n - i < kBurst ? n - i : kBurst;
    uint8_t s[2 * kBurst];
    if (!bus.read_regs(mpu::kAddress, mpu::kFifoRW, s, 2 * m)) return i;
    for (size_t j = 0; j < m; ++j) {
      const auto raw = static_cast<int16_t>(static_cast<uint16_t>(s[2 * j] << 8 | s[2 * j + 1]));
      // The newest sample is at now; earlier ones one period apart, never before the last one.
      uint64_t t = now_ns - uint64_t{mpu::kSamplePeriodNs} * (n - 1 - (i + j));
      if (t <= last_t_ns_) t = last_t_ns_ + 1;
      last_t_ns_ = t;
      out[i + j] = hal::GyroSample{t, mpu6050_rate_q24(raw)};
    }
  }
  return n;
}

}  // namespace lumavel::bluepill
