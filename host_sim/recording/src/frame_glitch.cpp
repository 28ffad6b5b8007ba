#include "lumavel/host/frame_glitch.hpp"

#include <cstdio>

namespace lumavel::host {

FrameGlitches skip_frame_glitches(std::vector<FramePairEntry>& frames, const std::vector<long>& lines,
                                  double period_s) {
  FrameGlitches g;
  if (frames.size() < 2 || !(period_s > 0)) return g;
  const double min_s = kFrameGlitchPeriods * period_s;
  std::vector<FramePairEntry> kept;
  kept.reserve(frames.size());
  kept.push_back(std::move(frames[0]));
  for (size_t k = 1; k < frames.size(); ++k) {
    const double dt = static_cast<double>(frames[k].t_ns - kept.back().t_ns) * 1e-9;
    if (dt < min_s) {
      if (g.count++ == 0) {
        g.first_line = k < lines.size() ? lines[k] : 0;
        g.first_t_ns = frames[k].t_ns;
        g.first_interval_s = dt;
      }
      continue;
    }
    kept.push_back(std::move(frames[k]));
  }
  frames = std::move(kept);
  return g;
}

std::string format_frame_glitches(const FrameGlitches& g, const std::string& cam_csv, double period_s) {
  char buf[640];
  const bool one = g.count == 1;
  std::snprintf(buf, sizeof buf,
                "%d frame pair%s skipped as %s (%s %s:%ld, t = %llu ns, %.6g s after the previous frame: below %g of "
                "the median frame period %.6g s is no frame; the estimator sees a dropped frame)",
                g.count, one ? "" : "s", one ? "a timing glitch" : "timing glitches", one ? "at" : "the first at",
                cam_csv.c_str(), g.first_line, static_cast<unsigned long long>(g.first_t_ns), g.first_interval_s,
                kFrameGlitchPeriods, period_s);
  return buf;
}

}  // namespace lumavel::host
