// The HAL camera and gyro of the blue pill: the two TSL1401CL as a 128 x 1
// stereo camera with a fixed exposure (= the frame period), and the MPU-6050
// FIFO drained into a ring of samples. While the camera waits for the end of
// an exposure it runs the board's idle work (USB, gyro FIFO).
#pragma once
#include <cstdint>

#include "i2c1.hpp"
#include "line_scan_adc.hpp"
#include "lumavel/bluepill/mpu6050.hpp"
#include "lumavel/hal/camera.hpp"
#include "lumavel/hal/gyro.hpp"
#include "system.hpp"

namespace bluepill {

class MpuGyro final : public lumavel::hal::Gyro {
 public:
  MpuGyro(I2c1& bus, SysTickClock& clock) : bus_(bus), clock_(clock) {}
  bool init() { return present_ = mpu_.init(bus_); }
  void poll();  // FIFO -> ring
  bool read(lumavel::hal::GyroSample& out) override;

 private:
  static constexpr int kRing = 64;
  I2c1& bus_;
  SysTickClock& clock_;
  lumavel::bluepill::Mpu6050 mpu_{};
  bool present_ = false;
  lumavel::hal::GyroSample ring_[kRing]{};
  int head_ = 0;
  int count_ = 0;
};

using IdleFn = void (*)(void* ctx);

class TslCamera final : public lumavel::hal::StereoCamera {
 public:
  static constexpr uint32_t kExposureNs = 10000000;  // 100 lines/s

  TslCamera(LineScanAdc& port, SysTickClock& clock, IdleFn idle, void* ctx)
      : port_(port), clock_(clock), idle_(idle), ctx_(ctx) {}
  void init();
  uint16_t width() const override { return lumavel::bluepill::kTslPixels; }
  uint16_t height() const override { return 1; }
  lumavel::hal::CaptureStatus capture(lumavel::hal::StereoImage& out) override;

 private:
  LineScanAdc& port_;
  SysTickClock& clock_;
  IdleFn idle_;
  void* ctx_;
  uint64_t start_ns_ = 0;  // start of the running integration
};

}  // namespace bluepill
