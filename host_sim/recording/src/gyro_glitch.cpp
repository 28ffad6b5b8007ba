#include "lumavel/host/gyro_glitch.hpp"

#include <cmath>
#include <cstdio>

namespace lumavel::host {

GyroGlitches repair_gyro_glitches(std::vector<ImuSample>& s, double period_s) {
  GyroGlitches g;
  const size_t n = s.size();
  const double hole_ns = kGapPeriods * period_s * 1e9;
  auto joined = [&](size_t k) { return static_cast<double>(s[k + 1].t_ns - s[k].t_ns) <= hole_ns; };  // k, k + 1
  for (size_t i = 1; i + 1 < n; ++i) {
    if (!joined(i - 1) || !joined(i)) continue;
    for (int j = 0; j < 3; ++j) {
      const double before = s[i - 1].w[j], after = s[i + 1].w[j];
      const double excursion = std::fabs(s[i].w[j] - (before + after) / 2);
      if (excursion <= kGyroGlitchMinRadS) continue;
      // Out and back: the neighbours agree with each other far better than with it.
      if (std::fabs(after - before) > excursion / 2) continue;
      double sum = 0;
      int terms = 0;
      for (size_t d = 2; d < 2 + static_cast<size_t>(kGyroGlitchWindow); ++d) {
        if (i >= d && joined(i - d)) {
          sum += std::fabs(s[i - d + 1].w[j] - s[i - d].w[j]);
          ++terms;
        }
        if (i + d < n && joined(i + d - 1)) {
          sum += std::fabs(s[i + d].w[j] - s[i + d - 1].w[j]);
          ++terms;
        }
      }
      if (terms < kGyroGlitchWindow) continue;
      if (excursion <= kGyroGlitchScatters * sum / terms) continue;
      if (g.count++ == 0) {
        g.first_index = i;
        g.first_axis = j;
        g.first_value = s[i].w[j];
        g.first_before = before;
        g.first_after = after;
      }
      s[i].w[j] = (before + after) / 2;
    }
  }
  return g;
}

std::string format_gyro_glitches(const GyroGlitches& g, const std::string& imu_csv) {
  static const char* const kAxis[3] = {"w_RS_S_x", "w_RS_S_y", "w_RS_S_z"};
  char buf[640];
  const bool one = g.count == 1;
  std::snprintf(buf, sizeof buf,
                "%d gyro value%s taken as %s and replaced by %s neighbours' mean (%s %s:%zu, %s %.6g rad/s between "
                "%.6g and %.6g: out and back within one sample by more than %g rad/s and %g times the scatter about "
                "it is no turn)",
                g.count, one ? "" : "s", one ? "a read glitch" : "read glitches", one ? "its" : "their",
                one ? "at" : "the first at", imu_csv.c_str(), g.first_index + 2, kAxis[g.first_axis], g.first_value,
                g.first_before, g.first_after, kGyroGlitchMinRadS, kGyroGlitchScatters);
  return buf;
}

}  // namespace lumavel::host
