#include "lumavel/host/run_metrics.hpp"

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <iterator>

#include "lumavel/core/status.hpp"

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
  const double median = sorted[sorted.size() / 2];
  w[0] = median * 1e-9;
  for (size_t i = 1; i < track.size(); ++i) w[i] = std::min(d[i - 1], kMaxWeightIntervals * median) * 1e-9;
  return w;
}

}  // namespace

RunMetrics compute_metrics(const std::vector<TrackPoint>& track, const MetricOptions& options) {
  RunMetrics m;
  m.options = options;
  m.samples = track.size();
  const std::vector<double> w = point_weights(track);
  const uint64_t t0 = track.empty() ? 0 : track.front().t_ns;
  if (!track.empty()) m.span_s = static_cast<double>(track.back().t_ns - t0) * 1e-9;
  // long double: the squares of any finite errors stay finite.
  long double e_num = 0, e_den = 0, abs_sum = 0, v_sum = 0, sq_sum = 0, after_abs = 0, after_signed = 0;
  size_t counted = 0;
  for (size_t i = 0; i < track.size(); ++i) {
    const TrackPoint& p = track[i];
    if (std::isnan(p.v_true)) continue;
    ++m.with_truth;
    if (!std::isfinite(p.v_est)) {
      ++m.not_finite;
      continue;
    }
    ++counted;
    const long double err = static_cast<long double>(p.v_est) - p.v_true;
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
      // (the first frame after it sets the time too: an estimate without any
      // error said "worst |err| 0 m/s at t = 0.000 s", inside the excluded second)
      if (std::fabs(err) > m.worst_after || m.after_count == 1) {
        m.worst_after = static_cast<double>(std::fabs(err));
        m.worst_after_t = t;
      }
    }
  }
  const double nan = std::nan("");
  m.e_percent = e_den > 0 ? static_cast<double>(100 * e_num / e_den) : nan;
  m.l1_percent = v_sum > 0 ? static_cast<double>(100 * abs_sum / v_sum) : nan;
  m.rms = counted ? static_cast<double>(std::sqrt(sq_sum / static_cast<long double>(counted))) : nan;
  m.mean_abs_after = m.after_count ? static_cast<double>(after_abs / static_cast<long double>(m.after_count)) : nan;
  m.mean_after = m.after_count ? static_cast<double>(after_signed / static_cast<long double>(m.after_count)) : nan;
  if (!m.after_count) m.worst_after = nan;
  return m;
}

namespace {

std::string printf_text(const char* f, ...) __attribute__((format(printf, 1, 2)));
std::string printf_text(const char* f, ...) {
  char buf[512];
  va_list ap;
  va_start(ap, f);
  std::vsnprintf(buf, sizeof buf, f, ap);
  va_end(ap);
  return buf;
}

// Why a figure over the frames with ground truth cannot be given.
std::string no_truth_reason(const RunMetrics& m) {
  if (m.with_truth == 0) return "no frame has ground truth";
  return "no estimate with ground truth is a finite number";
}

}  // namespace

std::string format_metrics(const RunMetrics& m) {
  std::string s = printf_text("ground truth: %zu of %zu frames", m.with_truth, m.samples);
  if (m.not_finite)
    s += printf_text("\n%zu estimates are not finite numbers (NaN or infinite): left out of every figure below",
                     m.not_finite);
  const bool any = m.with_truth > m.not_finite;
  if (std::isfinite(m.e_percent))
    s += printf_text("\nE (paper eq. 22, time average of |V_est - V|/|V|): %.2f %% (%zu frames with |V| < %.2f m/s excluded)",
                     m.e_percent, m.excluded_slow, m.options.min_speed);
  else if (!any)
    s += "\nE (paper eq. 22): no figure: " + no_truth_reason(m);
  else
    s += printf_text("\nE (paper eq. 22): no figure: |V| < %.2f m/s on every frame (the relative error is "
                     "undefined at standstill; see the RMS error)",
                     m.options.min_speed);
  if (std::isfinite(m.l1_percent)) s += printf_text("\nL1 error sum|err|/sum|V|: %.2f %%", m.l1_percent);
  else s += "\nL1 error: no figure: " + (any ? std::string("the true speed is 0 throughout") : no_truth_reason(m));
  if (std::isfinite(m.rms)) s += printf_text("\nRMS error: %.4g m/s", m.rms);
  else s += "\nRMS error: no figure: " + no_truth_reason(m);
  if (m.after_count)
    s += printf_text("\nafter the first %.1f s (%zu frames): worst |err| %.4g m/s at t = %.3f s, mean |err| %.4g m/s, "
                     "mean err %+.4g m/s",
                     m.options.settle_s, m.after_count, m.worst_after, m.worst_after_t, m.mean_abs_after, m.mean_after);
  else if (any && m.span_s < m.options.settle_s)
    s += printf_text("\nafter the first %.1f s: no figure: the run lasts %.3f s", m.options.settle_s, m.span_s);
  else if (any)  // a ground truth that stops early (was: "the run lasts 2.983 s", a run longer than the second)
    s += printf_text("\nafter the first %.1f s: no figure: no frame after it has ground truth (the run lasts %.3f s)",
                     m.options.settle_s, m.span_s);
  return s;
}

namespace {
constexpr uint16_t kNotFaults = kStatusConverging | kStatusStill | kStatusNoTof;
}  // namespace

bool is_fault(StatusFlag flag) { return (flag & kNotFaults) == 0; }

FlagCounts count_flags(const std::vector<TrackPoint>& track) {
  FlagCounts c;
  c.frames = track.size();
  for (const TrackPoint& p : track) {
    c.flagged += (p.status & ~kNotFaults) != 0;
    for (size_t k = 0; k < std::size(kStatusFlags); ++k) c.count[k] += (p.status & kStatusFlags[k].flag) != 0;
  }
  return c;
}

std::string format_flag_counts(const FlagCounts& c) {
  std::string s = printf_text("flags, frames of %zu:", c.frames);
  bool any = false;
  for (size_t k = 0; k < std::size(kStatusFlags); ++k) {
    if (!c.count[k]) continue;
    s += printf_text("%s %s %zu (%s)", any ? "," : "", kStatusFlags[k].name, c.count[k], kStatusFlags[k].meaning);
    any = true;
  }
  if (!any) s += " none raised";
  return s;
}

}  // namespace lumavel::host
