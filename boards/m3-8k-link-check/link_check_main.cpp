// Runs the estimator the way an 8 KiB part would: the device's default
// configuration at 40x30 (to_estimator_config, as the firmware app makes it),
// each camera's rows summed as they arrive (ColumnStream: no frame buffer,
// one 40-byte row at a time), then one step from the two profiles. Volatile
// inputs keep the compiler from folding any of it away, so the link pulls in
// everything a frame needs.
#include <cstdint>

#include "lumavel/app/estimator_config.hpp"
#include "lumavel/core/column_stream.hpp"
#include "lumavel/core/estimator.hpp"
#include "lumavel/protocol/device_config.hpp"

namespace {
constexpr uint16_t kW = 40;
constexpr uint16_t kH = 30;
lumavel::Estimator estimator;
lumavel::ColumnStream rows[2];
volatile int32_t sink;
volatile uint32_t input_seed = 1;
}  // namespace

int main() {
  lumavel::EstimatorConfig cfg{};
  const lumavel::protocol::DeviceConfig device = lumavel::protocol::defaults_for(kW, kH);
  sink = lumavel::app::to_estimator_config(device, cfg, nullptr) ? static_cast<int32_t>(estimator.configure(cfg)) : -1;
  uint64_t t = 0;
  for (;;) {
    uint32_t s = input_seed;
    for (auto& r : rows) r.start(kW, kH, estimator.bank().column_band());
    for (uint16_t y = 0; y < kH; ++y)
      for (auto& r : rows) {
        uint8_t line[kW];  // what a DMA line buffer would hold
        for (auto& p : line) {
          s = s * 1664525u + 1013904223u;
          p = static_cast<uint8_t>(s >> 24);
        }
        r.add_row(line, y);
      }
    input_seed = s;
    t += 16666667;
    estimator.push_gyro(t, static_cast<lumavel::RateQ24>(s >> 8));
    const lumavel::Estimate e = estimator.step_profiles(t, rows[0].profile(), rows[1].profile());
    sink = e.v + static_cast<int32_t>(e.distance) + e.heading + e.status;
  }
}
