#include "lumavel/host/track_plot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <stdexcept>

namespace lumavel::host {
namespace {

constexpr double kWidth = 960, kLeft = 80, kRight = 20, kPanelH = 260, kTop = 40, kGap = 60;

struct Axis {
  double lo, hi;
  double map(double v, double a, double b) const { return a + (v - lo) / (hi - lo) * (b - a); }
};

// 1, 2 or 5 times a power of ten, about range / 6.
double nice_step(double range) {
  const double raw = range / 6.0;
  const double p = std::pow(10.0, std::floor(std::log10(raw)));
  const double f = raw / p;
  return (f < 1.5 ? 1 : f < 3.5 ? 2 : f < 7.5 ? 5 : 10) * p;
}

Axis padded(double lo, double hi) {
  // A range of a few ulps is a constant: its tick step would be below the
  // resolution of the values and the tick loops would never end.
  if (!(hi - lo > 1e-9 * std::max({1.0, std::fabs(lo), std::fabs(hi)}))) {
    lo -= 0.5;
    hi += 0.5;
  }
  const double pad = 0.05 * (hi - lo);
  return {lo - pad, hi + pad};
}

std::string fmt(const char* f, double v) {
  char b[64];
  std::snprintf(b, sizeof b, f, v);
  return b;
}

// Polyline of (x, y) with at most ~2 points per pixel column (min and max).
std::string polyline(const std::vector<double>& x, const std::vector<double>& y, const Axis& ax, const Axis& ay,
                     double top, const char* colour) {
  std::string pts;
  const double x0 = kLeft, x1 = kWidth - kRight, y0 = top + kPanelH, y1 = top;
  long column = -1;
  double lo = 0, hi = 0, lo_x = 0, hi_x = 0;
  auto flush = [&] {
    if (column < 0) return;
    const bool lo_first = lo_x <= hi_x;
    const double a = lo_first ? lo : hi, b = lo_first ? hi : lo;
    pts += fmt("%.1f", static_cast<double>(column)) + "," + fmt("%.1f", ay.map(a, y0, y1)) + " ";
    if (b != a) pts += fmt("%.1f", static_cast<double>(column)) + "," + fmt("%.1f", ay.map(b, y0, y1)) + " ";
  };
  std::string out;
  auto end_line = [&] {
    flush();
    column = -1;
    if (!pts.empty()) out += "<polyline fill=\"none\" stroke=\"" + std::string(colour) +
                             "\" stroke-width=\"1.2\" points=\"" + pts + "\"/>\n";
    pts.clear();
  };
  for (size_t i = 0; i < x.size(); ++i) {
    if (std::isnan(y[i])) {  // no data: break the line
      end_line();
      continue;
    }
    const long c = std::lround(ax.map(x[i], x0, x1));
    if (c != column) {
      flush();
      column = c;
      lo = hi = y[i];
      lo_x = hi_x = x[i];
    } else {
      if (y[i] < lo) lo = y[i], lo_x = x[i];
      if (y[i] > hi) hi = y[i], hi_x = x[i];
    }
  }
  end_line();
  return out;
}

std::string panel_frame(const Axis& ax, const Axis& ay, double top, const std::string& ylabel, bool xlabels) {
  const double x0 = kLeft, x1 = kWidth - kRight, y0 = top + kPanelH, y1 = top;
  std::string s = "<rect x=\"" + fmt("%.1f", x0) + "\" y=\"" + fmt("%.1f", y1) + "\" width=\"" +
                  fmt("%.1f", x1 - x0) + "\" height=\"" + fmt("%.1f", kPanelH) +
                  "\" fill=\"white\" stroke=\"#444\"/>\n";
  const double sx = nice_step(ax.hi - ax.lo), sy = nice_step(ay.hi - ay.lo);
  for (double v = std::ceil(ax.lo / sx) * sx; v <= ax.hi; v += sx) {
    const double px = ax.map(v, x0, x1);
    s += "<line x1=\"" + fmt("%.1f", px) + "\" y1=\"" + fmt("%.1f", y1) + "\" x2=\"" + fmt("%.1f", px) +
         "\" y2=\"" + fmt("%.1f", y0) + "\" stroke=\"#ddd\"/>\n";
    if (xlabels)
      s += "<text x=\"" + fmt("%.1f", px) + "\" y=\"" + fmt("%.1f", y0 + 16) + "\" text-anchor=\"middle\">" +
           fmt("%g", std::fabs(v) < 1e-12 ? 0.0 : v) + "</text>\n";
  }
  for (double v = std::ceil(ay.lo / sy) * sy; v <= ay.hi; v += sy) {
    const double py = ay.map(v, y0, y1);
    s += "<line x1=\"" + fmt("%.1f", x0) + "\" y1=\"" + fmt("%.1f", py) + "\" x2=\"" + fmt("%.1f", x1) +
         "\" y2=\"" + fmt("%.1f", py) + "\" stroke=\"#ddd\"/>\n";
    s += "<text x=\"" + fmt("%.1f", x0 - 6) + "\" y=\"" + fmt("%.1f", py + 4) + "\" text-anchor=\"end\">" +
         fmt("%g", std::fabs(v) < 1e-12 ? 0.0 : v) + "</text>\n";
  }
  s += "<text transform=\"translate(18," + fmt("%.1f", top + kPanelH / 2) +
       ") rotate(-90)\" text-anchor=\"middle\">" + ylabel + "</text>\n";
  return s;
}

std::string escape(const std::string& t) {
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

}  // namespace

std::string track_svg(const std::vector<TrackPoint>& track, const std::string& title) {
  std::vector<double> t, est, truth, err;
  bool any_truth = false;
  const uint64_t t0 = track.empty() ? 0 : track.front().t_ns;
  for (const TrackPoint& p : track) {
    t.push_back(static_cast<double>(p.t_ns - t0) * 1e-9);
    est.push_back(p.v_est);
    truth.push_back(p.v_true);
    err.push_back(p.v_est - p.v_true);  // NaN without truth
    any_truth = any_truth || !std::isnan(p.v_true);
  }
  auto range = [](const std::vector<double>& a, const std::vector<double>& b) {
    double lo = INFINITY, hi = -INFINITY;
    for (const auto* v : {&a, &b})
      for (double x : *v)
        if (std::isfinite(x)) lo = std::min(lo, x), hi = std::max(hi, x);
    if (!(lo <= hi)) lo = hi = 0;
    return padded(lo, hi);
  };
  const Axis ax = t.empty() ? Axis{0, 1} : Axis{t.front(), t.back() > t.front() ? t.back() : t.front() + 1};
  const Axis av = range(est, truth);
  const int panels = any_truth ? 2 : 1;
  const double height = kTop + panels * kPanelH + (panels - 1) * kGap + 50;
  std::string s = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + fmt("%.0f", kWidth) + "\" height=\"" +
                  fmt("%.0f", height) + "\" font-family=\"sans-serif\" font-size=\"12\">\n";
  s += "<rect width=\"100%\" height=\"100%\" fill=\"#fafafa\"/>\n";
  s += "<text x=\"" + fmt("%.0f", kWidth / 2) + "\" y=\"24\" text-anchor=\"middle\" font-size=\"15\">" +
       escape(title) + "</text>\n";
  s += panel_frame(ax, av, kTop, "V (m/s)", panels == 1);
  if (any_truth) s += polyline(t, truth, ax, av, kTop, "#222");
  s += polyline(t, est, ax, av, kTop, "#1f6fd0");
  // Legend above the top panel, right-aligned, clear of the data.
  s += "<text x=\"" + fmt("%.0f", kWidth - kRight - (any_truth ? 130 : 0)) + "\" y=\"" + fmt("%.0f", kTop - 6) +
       "\" text-anchor=\"end\" fill=\"#1f6fd0\">estimate V_est</text>\n";
  if (any_truth) {
    s += "<text x=\"" + fmt("%.0f", kWidth - kRight) + "\" y=\"" + fmt("%.0f", kTop - 6) +
         "\" text-anchor=\"end\" fill=\"#222\">ground truth V</text>\n";
    const double top = kTop + kPanelH + kGap;
    // The error scale comes from the errors after the first second (as in the
    // paper's Fig. 4): the start-up frames would flatten everything else.
    // Earlier points beyond the scale are clipped to its edge.
    std::vector<double> settled;
    for (size_t i = 0; i < err.size(); ++i)
      if (t[i] >= 1.0) settled.push_back(err[i]);
    const Axis ae = range(settled.empty() ? err : settled, settled.empty() ? err : settled);
    std::vector<double> shown = err;
    for (double& e : shown)
      if (std::isfinite(e)) e = std::min(std::max(e, ae.lo), ae.hi);
    s += panel_frame(ax, ae, top, settled.empty() ? "V_est - V (m/s)" : "V_est - V (m/s), scaled after 1 s", true);
    s += polyline(t, shown, ax, ae, top, "#c0392b");
  }
  s += "<text x=\"" + fmt("%.0f", kWidth / 2) + "\" y=\"" + fmt("%.0f", height - 10) +
       "\" text-anchor=\"middle\">time (s)</text>\n</svg>\n";
  return s;
}

void write_track_svg(const std::string& path, const std::vector<TrackPoint>& track, const std::string& title) {
  std::ofstream out(path);
  out << track_svg(track, title);
  out.close();
  if (!out) throw std::runtime_error(path + ": cannot write the plot");
}

}  // namespace lumavel::host
