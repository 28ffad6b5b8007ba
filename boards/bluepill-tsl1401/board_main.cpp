// Blue pill (STM32F103C8) with two TSL1401CL line-scan sensors, an MPU-6050
// gyro and USB HID: start-up and the firmware app's endless frame loop.
#include <cstdint>

#include "clock_tree.hpp"
#include "flash_store.hpp"
#include "i2c1.hpp"
#include "line_scan_adc.hpp"
#include "lumavel/app/app.hpp"
#include "lumavel/board/static_object.hpp"
#include "lumavel/bluepill/usb_device.hpp"
#include "lumavel/protocol/device_config.hpp"
#include "sensors.hpp"
#include "stm32f1.hpp"
#include "system.hpp"
#include "usb_hid.hpp"

namespace {

// 128 x 1 line scan behind a 60 degree lens, 100 lines per second.
lumavel::protocol::DeviceConfig board_defaults() {
  // fu 110.85 px = 64 / tan(30 deg), cu 63.5 px.
  lumavel::protocol::DeviceConfig c = lumavel::protocol::defaults_for(lumavel::bluepill::kTslPixels, 1);
  c.frame_period_us = bluepill::TslCamera::kExposureNs / 1000;
  return c;
}

struct Board {
  bluepill::SysTickClock clock;
  bluepill::Iwdg watchdog;
  bluepill::LineScanAdc adc;
  bluepill::I2c1 i2c{clock};
  bluepill::MpuGyro gyro{i2c, clock};
  lumavel::bluepill::Descriptors descriptors{};
  bluepill::UsbHid usb{descriptors};
  bluepill::FlashStore store;
  bluepill::TslCamera camera{adc, clock, &Board::idle, this};

  static void idle(void* ctx) {
    auto* b = static_cast<Board*>(ctx);
    b->usb.poll();
    b->gyro.poll();
  }
};

lumavel::board::StaticObject<Board> board_storage;
lumavel::board::StaticObject<lumavel::app::App> app_storage;

}  // namespace

int main() {
  bluepill::clock_tree_init();
  Board& b = board_storage.emplace();
  b.clock.init();
  b.watchdog.init();
  stm32::rcc::apb2enr() |= 1u << 4;  // GPIOC: the LED on PC13 (low = on)
  stm32::kGpioC.mode(13, stm32::kOutPushPull2);

  uint8_t uid[12];
  for (uint32_t i = 0; i < 12; ++i) uid[i] = *reinterpret_cast<const volatile uint8_t*>(stm32::kUniqueId + i);
  lumavel::bluepill::build_descriptors(uid, b.descriptors);
  b.usb.init(b.clock);
  b.i2c.init();
  b.gyro.init();  // without a gyro the estimates carry kStatusGyroGap
  b.camera.init();

  lumavel::app::App& app = app_storage.emplace(
      lumavel::app::Hal{b.camera, b.gyro, b.clock, b.usb, b.store, b.watchdog},
      lumavel::app::Board{"bluepill-tsl1401", board_defaults()});
  app.start();
  for (uint32_t n = 0;; ++n) {
    app.run_once();
    if ((n & 31u) == 0) {
      (n & 32u) != 0 ? stm32::kGpioC.set(13) : stm32::kGpioC.clear(13);  // blink: alive
    }
  }
}
