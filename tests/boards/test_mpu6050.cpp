// MPU-6050 set-up and FIFO read-out against a simulated register file that
// records every I2C transaction (register map rev 4.2).
#include <CppUTest/TestHarness.h>

#include <cmath>
#include <cstdint>
#include <deque>
#include <vector>

#include "lumavel/bluepill/mpu6050.hpp"

namespace mpu = lumavel::bluepill::mpu;

namespace {

struct FakeMpu : lumavel::bluepill::I2cBus {
  uint8_t regs[128] = {};
  std::deque<uint8_t> fifo;
  std::vector<std::pair<uint8_t, uint8_t>> writes;  // (register, value) in bus order
  bool present = true;
  int delays = 0;
  FakeMpu() { regs[mpu::kWhoAmI] = mpu::kWhoAmIValue; }
  bool write_reg(uint8_t addr, uint8_t reg, uint8_t v) override {
    if (!present || addr != mpu::kAddress) return false;
    writes.emplace_back(reg, v);
    if (reg == mpu::kPwrMgmt1 && (v & 0x80) != 0) {  // DEVICE_RESET: registers to defaults
      for (auto& r : regs) r = 0;
      regs[mpu::kWhoAmI] = mpu::kWhoAmIValue;
      regs[mpu::kPwrMgmt1] = 0x40;  // asleep after reset
      return true;
    }
    if (reg == mpu::kUserCtrl && (v & 0x04) != 0) fifo.clear();  // FIFO_RESET self-clears
    regs[reg] = static_cast<uint8_t>(v & ~0x04);
    return true;
  }
  bool read_regs(uint8_t addr, uint8_t reg, uint8_t* buf, size_t n) override {
    if (!present || addr != mpu::kAddress) return false;
    for (size_t i = 0; i < n; ++i) {
      if (reg == mpu::kFifoRW) {
        buf[i] = fifo.empty() ? 0 : fifo.front();
        if (!fifo.empty()) fifo.pop_front();
      } else if (reg + i == mpu::kFifoCountH) {
        buf[i] = static_cast<uint8_t>(fifo.size() >> 8);
      } else if (reg + i == mpu::kFifoCountH + 1) {
        buf[i] = static_cast<uint8_t>(fifo.size());
      } else {
        buf[i] = regs[reg + i];
      }
    }
    return true;
  }
  void delay_ms(uint32_t) override { ++delays; }
  void push_sample(int16_t raw) {
    fifo.push_back(static_cast<uint8_t>(static_cast<uint16_t>(raw) >> 8));
    fifo.push_back(static_cast<uint8_t>(raw));
  }
};

}  // namespace

TEST_GROUP(Mpu6050){};

TEST(Mpu6050, SetUpLeavesTheDatasheetConfiguration) {
  FakeMpu bus;
  lumavel::bluepill::Mpu6050 dev;
  CHECK_TRUE(dev.init(bus));
  // Reset first, then a wait for it, then the configuration.
  CHECK_EQUAL(mpu::kPwrMgmt1, bus.writes.front().first);
  CHECK_EQUAL(0x80, bus.writes.front().second);
  CHECK_TRUE(bus.delays > 0);
  CHECK_EQUAL(0x01, bus.regs[mpu::kPwrMgmt1]);    // awake, PLL with the X gyro
  CHECK_EQUAL(0x03, bus.regs[mpu::kConfig]);      // DLPF 44 Hz -> gyro output 1 kHz
  CHECK_EQUAL(0x01, bus.regs[mpu::kSmplrtDiv]);   // 1 kHz / (1 + 1) = 500 Hz
  CHECK_EQUAL(0x08, bus.regs[mpu::kGyroConfig]);  // FS_SEL 1: +-500 deg/s
  CHECK_EQUAL(0x10, bus.regs[mpu::kFifoEn]);      // ZG only
  CHECK_EQUAL(0x40, bus.regs[mpu::kUserCtrl]);    // FIFO enabled
  CHECK_EQUAL(1000000000u / 500u, mpu::kSamplePeriodNs);
}

TEST(Mpu6050, RefusesADeviceThatIsNotAnMpu6050) {
  FakeMpu bus;
  bus.regs[mpu::kWhoAmI] = 0x70;  // MPU-6500
  lumavel::bluepill::Mpu6050 dev;
  CHECK_FALSE(dev.init(bus));
  CHECK_EQUAL(0u, bus.writes.size());
  FakeMpu absent;
  absent.present = false;
  CHECK_FALSE(dev.init(absent));
}

TEST(Mpu6050, RateConversionMatchesTheFullScale) {
  // 65.5 LSB per deg/s.
  for (int raw : {-32768, -655, -1, 0, 1, 655, 32767}) {
    const double want = raw / 65.5 * M_PI / 180.0 * (1 << 24);
    const double got = lumavel::bluepill::mpu6050_rate_q24(static_cast<int16_t>(raw));
    CHECK_TRUE_TEXT(std::fabs(got - want) <= 1.0 + std::fabs(want) * 4e-7, "rate conversion off");
  }
}

TEST(Mpu6050, FifoSamplesComeOutInOrderAndTimeStampedAtTheSampleRate) {
  FakeMpu bus;
  lumavel::bluepill::Mpu6050 dev;
  CHECK_TRUE(dev.init(bus));
  for (int i = 0; i < 20; ++i) bus.push_sample(static_cast<int16_t>(100 * i - 700));
  lumavel::hal::GyroSample s[32];
  const uint64_t now = 5000000000ull;
  CHECK_EQUAL(20u, dev.poll(bus, now, s, 32));  // two bursts (16 + 4)
  for (int i = 0; i < 20; ++i) {
    CHECK_EQUAL(lumavel::bluepill::mpu6050_rate_q24(static_cast<int16_t>(100 * i - 700)), s[i].rate_z);
    CHECK_EQUAL(now - uint64_t{mpu::kSamplePeriodNs} * static_cast<uint64_t>(19 - i), s[i].t_ns);
  }
  CHECK_TRUE(bus.fifo.empty());
  // Later samples never go back in time, even if the clock read early.
  bus.push_sample(5);
  CHECK_EQUAL(1u, dev.poll(bus, now - 1000, s, 32));
  CHECK_TRUE(s[0].t_ns > now);
}

TEST(Mpu6050, AnOverflowedFifoIsResetAndCounted) {
  FakeMpu bus;
  lumavel::bluepill::Mpu6050 dev;
  CHECK_TRUE(dev.init(bus));
  for (int i = 0; i < 512; ++i) bus.push_sample(1);
  lumavel::hal::GyroSample s[4];
  CHECK_EQUAL(0u, dev.poll(bus, 1000000, s, 4));
  CHECK_EQUAL(1u, dev.overflows());
  CHECK_TRUE(bus.fifo.empty());
}
