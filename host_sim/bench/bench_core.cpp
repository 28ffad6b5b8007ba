// Host time per stereo frame of the estimator core (fixed point) and of the
// double-precision reference, at 40x30 and 160x120. Run:
//   build/host_sim/bench/lumavel-bench-core
#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>
#include <vector>

#include "lumavel/core/column_profile.hpp"
#include "lumavel/core/estimator.hpp"
#include "lumavel/host/engine.hpp"
#include "lumavel/host/settings.hpp"

namespace {

using namespace lumavel;

host::EstimatorSettings settings(int w, int h) {
  host::EstimatorSettings s;
  s.width = w;
  s.height = h;
  const double hfov = 50 * M_PI / 180;
  for (int i = 0; i < 2; ++i) {
    s.cam[i].fu = w / 2.0 / std::tan(hfov / 2);
    s.cam[i].cu = (w - 1) / 2.0;
    s.cam[i].axis_yaw = M_PI / 2;
    s.cam[i].u_sign = -1;
  }
  s.kernels = host::default_kernels(hfov);
  s.normaliser = {0, hfov / 6};
  return s;
}

// A moving texture: frame i is the pattern shifted by i/4 pixel.
std::vector<std::vector<uint8_t>> frames(int w, int h, int n) {
  std::vector<std::vector<uint8_t>> out(static_cast<size_t>(n), std::vector<uint8_t>(static_cast<size_t>(w * h)));
  for (int i = 0; i < n; ++i)
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        out[static_cast<size_t>(i)][static_cast<size_t>(y * w + x)] =
            static_cast<uint8_t>(128 + 60 * std::sin((x + i / 4.0) * 0.4) * std::cos(y * 0.3));
  return out;
}

void BM_ColumnProfile(benchmark::State& st) {
  const int w = static_cast<int>(st.range(0)), h = static_cast<int>(st.range(1));
  const auto f = frames(w, h, 1);
  ColumnProfile p;
  for (auto _ : st) {
    column_profile(f[0].data(), static_cast<uint16_t>(w), static_cast<uint16_t>(h), static_cast<uint16_t>(w), nullptr, p);
    benchmark::DoNotOptimize(p);
  }
  st.counters["ns/pixel"] = benchmark::Counter(static_cast<double>(w * h), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

void BM_Engine(benchmark::State& st, host::EngineKind kind) {
  const int w = static_cast<int>(st.range(0)), h = static_cast<int>(st.range(1));
  auto eng = host::make_engine(kind, settings(w, h));
  const auto f = frames(w, h, 64);
  uint64_t t = 0;
  size_t i = 0;
  for (auto _ : st) {
    t += 16666667;
    eng->push_gyro(t, 0.01);
    benchmark::DoNotOptimize(eng->step(t, f[i % 64].data(), f[(i + 1) % 64].data()));
    ++i;
  }
  st.SetItemsProcessed(st.iterations());
}

void BM_Configure(benchmark::State& st) {
  const EstimatorConfig c = host::to_fixed_config(settings(static_cast<int>(st.range(0)), 30));
  auto est = std::make_unique<Estimator>();
  for (auto _ : st) benchmark::DoNotOptimize(est->configure(c));
}

}  // namespace

BENCHMARK(BM_ColumnProfile)->Args({40, 30})->Args({160, 120});
BENCHMARK_CAPTURE(BM_Engine, fixed, lumavel::host::EngineKind::kFixed)->Args({40, 30})->Args({160, 120});
BENCHMARK_CAPTURE(BM_Engine, float, lumavel::host::EngineKind::kFloat)->Args({40, 30})->Args({160, 120});
BENCHMARK(BM_Configure)->Arg(40)->Arg(160)->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
