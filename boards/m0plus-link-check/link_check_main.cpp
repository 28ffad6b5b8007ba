// Calls the estimator the way the firmware does (configure once, then step
// per frame with gyro samples) so that the link pulls in everything a frame
// needs. Volatile inputs keep the compiler from folding any of it away.
#include <cstdint>

#include "lumavel/core/estimator.hpp"

namespace {
constexpr uint16_t kW = 40;
constexpr uint16_t kH = 30;
uint8_t frame[2][kW * kH];
lumavel::Estimator estimator;
volatile int32_t sink;
volatile uint32_t input_seed = 1;

lumavel::EstimatorConfig make_config() {
  lumavel::EstimatorConfig c{};
  c.width = kW;
  c.height = kH;
  for (auto& cam : c.cam) {
    cam.fu = 35 << 16;
    cam.cu = (kW - 1) << 15;
    cam.axis_yaw = -lumavel::fx::kPiQ28 / 2;
    cam.u_sign = -1;
  }
  c.baseline = (8 << 24) / 100;
  c.normaliser = {0, (2 << 28) / 10};
  c.kernels[0] = {1, (7 << 28) / 100};
  c.kernels[1] = {2, (1 << 28) / 10};
  c.kernel_count = 2;
  c.tau_us = 100000;
  c.frame_period_us = 16667;
  c.max_gap_us = 500000;
  c.gyro_gap_us = 50000;
  c.low_texture = (2 << 28) / 1000;
  c.saturated_permille = 50;
  return c;
}
}  // namespace

int main() {
  const lumavel::EstimatorConfig cfg = make_config();
  sink = static_cast<int32_t>(estimator.configure(cfg));
  uint64_t t = 0;
  for (;;) {
    uint32_t s = input_seed;
    for (auto& cam : frame)
      for (auto& p : cam) {
        s = s * 1664525u + 1013904223u;
        p = static_cast<uint8_t>(s >> 24);
      }
    input_seed = s;
    t += 16666667;
    estimator.push_gyro(t, static_cast<lumavel::RateQ24>(s >> 8));
    const lumavel::FramePair pair{t, {frame[0], frame[1]}, kW};
    const lumavel::Estimate e = estimator.step(pair);
    sink = e.v + static_cast<int32_t>(e.distance) + e.heading + e.status;
  }
}
