// The app under test wired to a fresh set of HAL fakes and the protocol's
// default configuration, shared by the app test suites.
#pragma once
#include <cstdint>

#include "fake_hal.hpp"
#include "lumavel/app/app.hpp"
#include "lumavel/protocol/device_config.hpp"

namespace {

constexpr uint64_t kPeriod = 16667000;  // default frame_period_us, in ns

struct Env {
  fake::Camera camera;
  fake::Gyro gyro;
  fake::Clock clock;
  fake::Link link;
  fake::Store store;
  fake::Watchdog watchdog;
  lumavel::app::App app{lumavel::app::Hal{camera, gyro, clock, link, store, watchdog},
                        lumavel::app::Board{"test-board", lumavel::protocol::default_device_config()}};
};

}  // namespace
