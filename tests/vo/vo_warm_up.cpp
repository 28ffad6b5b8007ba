// OpenCV allocates its thread pool, TLS buffers and tables on first use and
// keeps them; CppUTest's leak check would blame them on whichever test
// uses the VO first. One short VO run before any test allocates them all.
#include <cmath>
#include <vector>

#include "lumavel/host/vo_engine.hpp"
#include "recording_fixture.hpp"

namespace {

bool warm_up_opencv() {
  lumavel::host::Recording r;
  r.root = "/warm-up";
  r.cam[0] = fixture::left_camera(40, 30, -0.04);
  r.cam[1] = fixture::left_camera(40, 30, 0.04);
  r.frame_period_s = 0.01;
  const auto vo = lumavel::host::make_vo_engine(r, 40, 30);
  std::vector<uint8_t> a(1200), b(1200);
  for (int f = 0; f < 3; ++f) {
    for (int i = 0; i < 1200; ++i) {
      const double x = i % 40 + 0.4 * f, y = i / 40;
      a[static_cast<size_t>(i)] = static_cast<uint8_t>(128 + 60 * std::sin(0.7 * x) * std::cos(0.6 * y));
      b[static_cast<size_t>(i)] = static_cast<uint8_t>(128 + 60 * std::sin(0.7 * (x + 1.5)) * std::cos(0.6 * y));
    }
    vo->push_gyro(static_cast<uint64_t>(f) * 10000000u, 0.0);
    vo->step(static_cast<uint64_t>(f) * 10000000u, a.data(), b.data());
  }
  return true;
}

const bool kOpenCvWarm = warm_up_opencv();

}  // namespace
