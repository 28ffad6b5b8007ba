#include "lumavel/host/run_metrics.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace lumavel::host {
namespace {

std::vector<double> point_weights(const std::vector<TrackPoint>& track) {
  std::vector<double> w(track.size(), 0.0);
  if (track.size() < 2) {
    std::fill(w.begin(), w.end(), 1.0);
    return w;
  }
  std::vector<double> d;
  for (size_t i = 1; i < track.size(); ++i) d.push_back(static_cast<double>(track[i].t_ns - track[i - 1].t_ns));
  std::vector<double> sorted = d;
  std::nth_element(sorted.begin(), sorted.begin() + static_cast<long>(sorted.size() / 2), sorted.end());
  w[0] = sorted[sorted.size() / 2] * 1e-9;
  for (size_t i = 1; i < track.size(); ++i) w[i] = d[i - 1] * 1e-9;
  return w;
}

}  // namespace

RunMetrics compute_metrics(const std::vector<TrackPoint>& track, const MetricOptions& options) {
  RunMetrics m;
  m.options = options;
  m.samples = track.size();
  const std::vector<double> w = point_weights(track);
  const uint64_t t0 = track.empty() ? 0 : track.front().t_ns;
  double e_num = 0, e_den = 0, abs_sum = 0, v_sum = 0, sq_sum = 0, after_abs = 0, after_signed = 0;
  for (size_t i = 0; i < track.size(); ++i) {
    const TrackPoint& p = track[i];
    if (std::isnan(p.v_true)) continue;
    ++m.with_truth;
    const double err = p.v_est - p.v_true;
    abs_sum += std::fabs(err);
    v_sum += std::fabs(p.v_true);
    sq_sum += err * err;
    if (std::fabs(p.v_true) < options.min_speed) {
      ++m.excluded_slow;
    } else {
      e_num += w[i] * std::fabs(err) / std::fabs(p.v_true);
      e_den += w[i];
    }
    const double t = static_cast<double>(p.t_ns - t0) * 1e-9;
    if (t >= options.settle_s) {
      ++m.after_count;
      after_abs += std::fabs(err);
      after_signed += err;
      if (std::fabs(err) > m.worst_after) {
        m.worst_after = std::fabs(err);
        m.worst_after_t = t;
      }
    }
  }
  const double nan = std::nan("");
  m.e_percent = e_den > 0 ? 100.0 * e_num / e_den : nan;
  m.l1_percent = v_sum > 0 ? 100.0 * abs_sum / v_sum : nan;
  m.rms = m.with_truth ? std::sqrt(sq_sum / static_cast<double>(m.with_truth)) : nan;
  m.mean_abs_after = m.after_count ? after_abs / static_cast<double>(m.after_count) : nan;
  m.mean_after = m.after_count ? after_signed / static_cast<double>(m.after_count) : nan;
  if (!m.after_count) m.worst_after = nan;
  return m;
}

std::string format_metrics(const RunMetrics& m) {
  char buf[1024];
  std::snprintf(buf, sizeof buf,
                "ground truth: %zu of %zu frames\n"
                "E (paper eq. 22, time average of |V_est - V|/|V|): %.2f %%"
                " (%zu frames with |V| < %.2f m/s excluded)\n"
                "L1 error sum|err|/sum|V|: %.2f %%\n"
                "RMS error: %.4f m/s\n"
                "after the first %.1f s (%zu frames): worst |err| %.4f m/s at t = %.3f s,"
                " mean |err| %.4f m/s, mean err %+.4f m/s",
                m.with_truth, m.samples, m.e_percent, m.excluded_slow, m.options.min_speed, m.l1_percent, m.rms,
                m.options.settle_s, m.after_count, m.worst_after, m.worst_after_t, m.mean_abs_after, m.mean_after);
  return buf;
}

}  // namespace lumavel::host
