#include "svg_axis.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "lumavel/host/path_check.hpp"

namespace lumavel::host::svg {

std::string fmt(const char* f, double v) {
  char b[64];
  std::snprintf(b, sizeof b, f, v);
  return b;
}

// Text for an SVG (UTF-8 XML): its markup characters as entities, and what
// XML cannot hold, control characters and bytes that are no UTF-8, shown as
// \xNN (shown_text): a recording folder named 'e<ESC>[2Jrec', whose name is
// the plot's title, made a plot no browser opens ('not well-formed'), exit 0.
std::string escape(const std::string& text) {
  const std::string t = shown_text(text);
  std::string o;
  for (char c : t) {
    if (c == '<') o += "&lt;";
    else if (c == '>') o += "&gt;";
    else if (c == '&') o += "&amp;";
    else if (c == '"') o += "&quot;";
    else o += c;
  }
  return o;
}

Axis robust_range(std::vector<double> v, double tail, double min_span) {
  v.erase(std::remove_if(v.begin(), v.end(), [](double x) { return !std::isfinite(x); }), v.end());
  if (v.empty()) return {0, 1};
  std::sort(v.begin(), v.end());
  const size_t cut = static_cast<size_t>(tail * static_cast<double>(v.size()));
  double lo = v[cut], hi = v[v.size() - 1 - cut];
  if (hi - lo < min_span) {
    const double mid = 0.5 * (lo + hi);
    lo = mid - 0.5 * min_span;
    hi = mid + 0.5 * min_span;
  }
  const double pad = 0.08 * (hi - lo);
  return {lo - pad, hi + pad};
}

Axis with_headroom(Axis a, double pixels, double room) {
  if (room <= 0 || room >= pixels) return a;
  a.hi += (a.hi - a.lo) * room / (pixels - room);
  return a;
}

Axis including(Axis a, double v) {
  if (!std::isfinite(v)) return a;
  const double pad = 0.04 * (a.hi - a.lo);
  if (v < a.lo + pad) a.lo = v - pad;
  if (v > a.hi - pad) a.hi = v + pad;
  return a;
}

namespace {

// 1, 2 or 5 times a power of ten, at least `raw`.
double nice_at_least(double raw) {
  const double p = std::pow(10.0, std::floor(std::log10(raw)));
  const double f = raw / p;
  return (f <= 1 ? 1 : f <= 2 ? 2 : f <= 5 ? 5 : 10) * p;
}

// 1, 2 or 5 times a power of ten, the nearest to `raw`.
double nice_near(double raw) {
  const double p = std::pow(10.0, std::floor(std::log10(raw)));
  const double f = raw / p;
  return (f < 1.5 ? 1 : f < 3.5 ? 2 : f < 7.5 ? 5 : 10) * p;
}

std::string label_for(double v, double step) {
  if (std::fabs(v) < step * 1e-9) v = 0;
  const double mag = std::max(std::fabs(v), step);
  if (mag >= 1e6 || step < 1e-4) return fmt("%.3g", v);  // exponent form stays short
  const int decimals = std::max(0, static_cast<int>(std::ceil(-std::log10(step) - 1e-9)));
  char b[64];
  std::snprintf(b, sizeof b, "%.*f", decimals, v);
  return b;
}

}  // namespace

std::vector<Tick> ticks(const Axis& a, double pixels, bool horizontal) {
  const double range = a.hi - a.lo;
  std::vector<Tick> out;
  if (!(range > 0) || !std::isfinite(range)) return out;
  // Start from about one tick per 80 px (40 px upright) and widen the step
  // until the labels fit.
  double step = nice_near(range / std::max(2.0, pixels / (horizontal ? 80.0 : 40.0)));
  for (int attempt = 0; attempt < 20; ++attempt) {
    out.clear();
    size_t widest = 0;
    const double first = std::ceil(a.lo / step) * step;
    for (int k = 0; k < 1000; ++k) {
      const double v = first + k * step;
      if (v > a.hi + step * 1e-9) break;
      out.push_back({v, label_for(v, step)});
      widest = std::max(widest, out.back().label.size());
    }
    const double spacing = pixels * step / range;
    const double needed = horizontal ? 7.0 * static_cast<double>(widest) + 12 : 18;
    if (spacing >= needed) break;
    step = nice_at_least(step * 1.01);
  }
  return out;
}

}  // namespace lumavel::host::svg
