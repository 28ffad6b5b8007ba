#include "lumavel/host/time_shift_pairing.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace lumavel::host {

double slider_position_at(const std::vector<SliderPose>& poses, double t) {
  if (poses.empty() || t < poses.front().t || t > poses.back().t) return std::numeric_limits<double>::quiet_NaN();
  auto hi = std::lower_bound(poses.begin(), poses.end(), t, [](const SliderPose& p, double v) { return p.t < v; });
  if (hi == poses.begin()) return hi->p[0];
  const SliderPose& b = *hi;
  const SliderPose& a = *(hi - 1);
  const double w = (t - a.t) / (b.t - a.t);
  return a.p[0] + w * (b.p[0] - a.p[0]);
}

std::vector<ShiftedPair> plan_time_shift_pairs(const std::vector<double>& x, double h) {
  std::vector<ShiftedPair> pairs;
  for (size_t i = 0; i < x.size(); ++i) {
    if (std::isnan(x[i])) continue;
    const double target = x[i] + h;
    // The first frame at or past the target, then its predecessor brackets it.
    for (size_t k = i + 1; k < x.size(); ++k) {
      if (std::isnan(x[k]) || std::isnan(x[k - 1])) continue;
      if (x[k] >= target && x[k - 1] < target) {
        pairs.push_back({i, k - 1, (target - x[k - 1]) / (x[k] - x[k - 1])});
        break;
      }
    }
  }
  return pairs;
}

void blend_gray(const uint8_t* a, const uint8_t* b, double w, size_t n, uint8_t* out) {
  for (size_t p = 0; p < n; ++p) {
    const double v = (1.0 - w) * a[p] + w * b[p];
    out[p] = static_cast<uint8_t>(std::clamp(std::lround(v), 0L, 255L));
  }
}

}  // namespace lumavel::host
