#include "lumavel/host/track_plot.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <stdexcept>

#include "lumavel/core/status.hpp"
#include "lumavel/host/output_file.hpp"
#include "svg_axis.hpp"

namespace lumavel::host {
namespace {

using svg::Axis;
using svg::escape;
using svg::fmt;

// Layout, px.
constexpr double kWidth = 960, kLeft = 104, kRight = 24;
constexpr double kX0 = kLeft, kX1 = kWidth - kRight;
constexpr double kTitleY = 22, kStatsY = 42, kTop = 56;
constexpr double kSpeedH = 250, kErrorH = 200, kGap = 14, kLaneH = 11, kLaneGap = 3;

// Colours (Okabe-Ito, distinguishable with colour-blindness).
constexpr const char* kEstimateColour = "#0072B2";
constexpr const char* kTruthColour = "#9a9a9a";
constexpr const char* kErrorColour = "#D55E00";

// Faults (is_fault) are also shaded across the panels.
struct FlagStyle {
  StatusFlag flag;
  const char* colour;
};
constexpr FlagStyle kFlagStyles[] = {
    {kStatusConverging, "#c8c8c8"}, {kStatusLowTexture, "#E69F00"}, {kStatusSaturated, "#CC79A7"},
    {kStatusFrameGap, "#56B4E9"},   {kStatusGyroGap, "#009E73"},    {kStatusNoLight, "#333333"},
    {kStatusRestarted, "#8B4513"},  {kStatusStill, "#9ecae1"},      {kStatusNoStereo, "#F0E442"},
    {kStatusNoTof, "#dadaeb"},      {kStatusAgainstImages, "#b2182b"},
};
static_assert(sizeof(kFlagStyles) / sizeof(kFlagStyles[0]) == sizeof(kStatusFlags) / sizeof(kStatusFlags[0]),
              "a style for every status flag");

const StatusFlagInfo& info_of(StatusFlag f) {
  for (const StatusFlagInfo& i : kStatusFlags)
    if (i.flag == f) return i;
  return kStatusFlags[0];
}

std::string px(double v) { return fmt("%.1f", v); }

struct Panel {
  double top, height;
  double bottom() const { return top + height; }
};

// Time spans (s) where `flag` is raised, merged when closer than a pixel.
// A frame covers half an interval on each side; a frame gap covers the gap.
std::vector<std::pair<double, double>> flag_runs(const std::vector<double>& t, const std::vector<uint16_t>& status,
                                                 StatusFlag flag, const Axis& ax) {
  std::vector<std::pair<double, double>> runs;
  const double half = t.size() > 1 ? 0.5 * (t.back() - t.front()) / static_cast<double>(t.size() - 1) : 0.5;
  const double pixel = (ax.hi - ax.lo) / (kX1 - kX0);
  for (size_t i = 0; i < t.size(); ++i) {
    if (!(status[i] & flag)) continue;
    double a = t[i] - half, b = t[i] + half;
    if (flag == kStatusFrameGap && i > 0) a = t[i - 1], b = t[i];
    if (b - a < 1.5 * pixel) a -= 0.75 * pixel, b += 0.75 * pixel;  // a single frame stays visible
    if (!runs.empty() && a <= runs.back().second + pixel) runs.back().second = std::max(runs.back().second, b);
    else runs.emplace_back(a, b);
  }
  for (auto& r : runs) r = {std::max(r.first, ax.lo), std::min(r.second, ax.hi)};
  return runs;
}

std::string rect(double x0, double y0, double x1, double y1, const char* fill, double opacity) {
  return "<rect x=\"" + px(x0) + "\" y=\"" + px(y0) + "\" width=\"" + px(std::max(x1 - x0, 0.5)) + "\" height=\"" +
         px(y1 - y0) + "\" fill=\"" + fill + "\" fill-opacity=\"" + fmt("%.2f", opacity) + "\"/>\n";
}

std::string text(double x, double y, const std::string& s, const char* anchor = "start", const char* extra = "") {
  return "<text x=\"" + px(x) + "\" y=\"" + px(y) + "\" text-anchor=\"" + anchor + "\"" + extra + ">" + escape(s) +
         "</text>\n";
}

// The line of (t, v) in a panel: at most two points per pixel column (min
// and max), broken where v is NaN; isolated points as dots. Values beyond the
// axis are drawn on its edge; each run of them gets a triangle there.
struct Line {
  std::string svg;
  size_t clipped = 0;     // points drawn on an edge
  double lowest = INFINITY, highest = -INFINITY;  // of those below and above the axis
  std::vector<std::pair<double, double>> drawn;  // the points drawn, px (for the legend's place)
};

Line line(const std::vector<double>& t, const std::vector<double>& v, const Axis& ax, const Axis& ay, const Panel& p,
          const char* colour, double width) {
  Line out;
  std::string pts, markers;
  size_t seg_points = 0;
  double last_x = 0, last_y = 0;
  long column = -1;
  double lo = 0, hi = 0, lo_x = 0, hi_x = 0;
  auto y_of = [&](double val) { return ay.map(val, p.bottom(), p.top); };
  auto flush_column = [&] {
    if (column < 0) return;
    const bool lo_first = lo_x <= hi_x;
    const double a = lo_first ? lo : hi, b = lo_first ? hi : lo;
    pts += px(static_cast<double>(column)) + "," + px(y_of(a)) + " ";
    ++seg_points;
    last_x = static_cast<double>(column);
    last_y = y_of(a);
    out.drawn.emplace_back(last_x, last_y);
    if (b != a) {
      pts += px(static_cast<double>(column)) + "," + px(y_of(b)) + " ";
      ++seg_points;
      out.drawn.emplace_back(last_x, y_of(b));
    }
  };
  auto end_segment = [&] {
    flush_column();
    column = -1;
    if (seg_points == 1)
      out.svg += "<circle cx=\"" + px(last_x) + "\" cy=\"" + px(last_y) + "\" r=\"" + fmt("%.1f", width + 1.5) +
                 "\" fill=\"" + colour + "\"/>\n";
    else if (seg_points > 1)
      out.svg += "<polyline fill=\"none\" stroke=\"" + std::string(colour) + "\" stroke-width=\"" + fmt("%.1f", width) +
                 "\" stroke-linejoin=\"round\" points=\"" + pts + "\"/>\n";
    pts.clear();
    seg_points = 0;
  };
  int side = 0;  // the side of the current run of clipped points
  long last_marker_col[2] = {-10, -10};  // below, above
  for (size_t i = 0; i < t.size(); ++i) {
    if (!std::isfinite(v[i])) {  // no data: break the line
      end_segment();
      side = 0;
      continue;
    }
    double val = v[i];
    const int s = val > ay.hi ? 1 : val < ay.lo ? -1 : 0;
    if (s != 0) {
      ++out.clipped;
      if (s < 0) out.lowest = std::min(out.lowest, val);
      else out.highest = std::max(out.highest, val);
      val = s > 0 ? ay.hi : ay.lo;
      const long c = std::lround(ax.map(t[i], kX0, kX1));
      long& last = last_marker_col[s > 0];
      if (s != side && c > last + 3) {  // one triangle per run, a few pixels apart on each edge
        const double x = static_cast<double>(c), y = s > 0 ? p.top : p.bottom(), d = s > 0 ? 7 : -7;
        markers += "<path d=\"M" + px(x - 4) + "," + px(y + d) + " L" + px(x + 4) + "," + px(y + d) + " L" + px(x) +
                   "," + px(y) + " Z\" fill=\"" + colour + "\"/>\n";
        last = c;
      }
    }
    side = s;
    const long c = std::lround(ax.map(t[i], kX0, kX1));
    if (c != column) {
      flush_column();
      column = c;
      lo = hi = val;
      lo_x = hi_x = t[i];
    } else {
      if (val < lo) lo = val, lo_x = t[i];
      if (val > hi) hi = val, hi_x = t[i];
    }
  }
  end_segment();
  out.svg += markers;
  return out;
}

std::string frame(const Panel& p, const Axis& ax, const Axis& ay, const std::string& ylabel) {
  std::string s = "<rect x=\"" + px(kX0) + "\" y=\"" + px(p.top) + "\" width=\"" + px(kX1 - kX0) + "\" height=\"" +
                  px(p.height) + "\" fill=\"white\" stroke=\"#444\"/>\n";
  for (const svg::Tick& k : svg::ticks(ax, kX1 - kX0, true)) {
    const double x = ax.map(k.value, kX0, kX1);
    s += "<line x1=\"" + px(x) + "\" y1=\"" + px(p.top) + "\" x2=\"" + px(x) + "\" y2=\"" + px(p.bottom()) +
         "\" stroke=\"#e4e4e4\"/>\n";
  }
  for (const svg::Tick& k : svg::ticks(ay, p.height, false)) {
    const double y = ay.map(k.value, p.bottom(), p.top);
    s += "<line x1=\"" + px(kX0) + "\" y1=\"" + px(y) + "\" x2=\"" + px(kX1) + "\" y2=\"" + px(y) + "\" stroke=\"" +
         (k.value == 0 ? "#999" : "#e4e4e4") + "\"/>\n";
    s += text(kX0 - 6, y + 4, k.label, "end");
  }
  s += "<text transform=\"translate(16," + px(p.top + p.height / 2) + ") rotate(-90)\" text-anchor=\"middle\">" +
       escape(ylabel) + "</text>\n";
  return s;
}

double legend_height(size_t entries) { return 8 + 16.0 * static_cast<double>(entries); }

// A legend box inside the panel, in the top corner that hides the fewest
// of the points drawn (the axes leave headroom for it): entries of
// (sample, words).
std::string legend(const Panel& p, const std::vector<std::pair<std::string, std::string>>& entries,
                   const std::vector<const Line*>& lines) {
  size_t widest = 0;
  for (const auto& e : entries) widest = std::max(widest, e.second.size());
  const double w = 44 + 6.6 * static_cast<double>(widest), h = legend_height(entries.size());
  double x = kX1 - w - 8, y = p.top + 8;
  size_t fewest = SIZE_MAX;
  for (const auto& [cx, cy] : {std::pair<double, double>{kX1 - w - 8, p.top + 8}, {kX0 + 8, p.top + 8}}) {
    size_t hidden = 0;
    for (const Line* l : lines)
      for (const auto& [lx, ly] : l->drawn) hidden += lx >= cx - 4 && lx <= cx + w + 4 && ly >= cy - 4 && ly <= cy + h + 4;
    if (hidden < fewest) fewest = hidden, x = cx, y = cy;
  }
  std::string s = "<rect x=\"" + px(x) + "\" y=\"" + px(y) + "\" width=\"" + px(w) + "\" height=\"" + px(h) +
                  "\" fill=\"white\" fill-opacity=\"0.88\" stroke=\"#bbb\"/>\n";
  for (size_t i = 0; i < entries.size(); ++i) {
    const double yy = y + 14 + 16.0 * static_cast<double>(i);
    s += "<g transform=\"translate(" + px(x + 8) + "," + px(yy - 4) + ")\">" + entries[i].first + "</g>\n";
    s += text(x + 38, yy, entries[i].second);
  }
  return s;
}

// The width of a key entry under the time axis: swatch, words at 11 px
// (DejaVu Sans averages about 6.3 px a character there, capitals more), gap.
double key_entry_width(const std::string& words) { return 14 + 6.6 * static_cast<double>(words.size()) + 16; }

std::string frames_text(size_t n) { return std::to_string(n) + (n == 1 ? " frame" : " frames"); }

// "down to -0.5, up to 6.7 m/s": how far beyond the axis the clipped points lie.
std::string beyond_text(const Line& l, const char* format) {
  std::string s;
  if (std::isfinite(l.lowest)) s += "down to " + fmt(format, l.lowest);
  if (std::isfinite(l.highest)) s += (s.empty() ? "up to " : ", up to ") + fmt(format, l.highest);
  return s + " m/s";
}

std::string sample_line(const char* colour, double width) {
  return "<line x1=\"0\" y1=\"0\" x2=\"24\" y2=\"0\" stroke=\"" + std::string(colour) + "\" stroke-width=\"" +
         fmt("%.1f", width) + "\"/>";
}

std::string sample_triangle(const char* colour) {
  return "<path d=\"M8,-5 L16,-5 L12,2 Z\" fill=\"" + std::string(colour) + "\"/>";
}

#define kSep " \u00b7 "

// The figures of the run, said on one line above the panels.
std::string stats_line(const RunMetrics& m, bool any_truth, const FlagCounts& flags) {
  std::string s;
  if (!any_truth) {
    s = "no ground truth: no error figures";
  } else {
    s = std::isfinite(m.e_percent) ? fmt("E %.2f %%", m.e_percent) : std::string("E: no figure (|V| < 0.05 m/s)");
    if (std::isfinite(m.l1_percent)) s += fmt(kSep "L1 %.2f %%", m.l1_percent);
    if (std::isfinite(m.rms)) s += kSep "RMS " + fmt("%.3g m/s", m.rms);
    if (m.after_count)
      s += kSep "worst |err| after " + fmt("%.0f s ", m.options.settle_s) + fmt("%.3g m/s", m.worst_after) +
           fmt(" at %.2f s", m.worst_after_t);
  }
  const double share = flags.frames ? 100.0 * static_cast<double>(flags.flagged) / static_cast<double>(flags.frames) : 0;
  // Faults only: CONVERGING, STILL and NO_TOF say how V is made, not that it is wrong.
  s += flags.flagged ? fmt(kSep "a fault flagged on %.0f %% of frames", share) : std::string(kSep "no fault flagged");
  return s;
}

}  // namespace

std::string track_svg(const std::vector<TrackPoint>& track, const std::string& title) {
  std::vector<double> t, est, truth, err;
  std::vector<uint16_t> status;
  bool any_truth = false;
  const uint64_t t0 = track.empty() ? 0 : track.front().t_ns;
  for (const TrackPoint& p : track) {
    t.push_back(static_cast<double>(p.t_ns - t0) * 1e-9);
    est.push_back(p.v_est);
    truth.push_back(p.v_true);
    err.push_back(p.v_est - p.v_true);  // NaN without truth
    status.push_back(p.status);
    any_truth = any_truth || !std::isnan(p.v_true);
  }
  const RunMetrics metrics = compute_metrics(track);
  const FlagCounts counts = count_flags(track);
  const double settle = metrics.options.settle_s;

  const Axis ax = t.empty() || !(t.back() > t.front()) ? Axis{t.empty() ? 0 : t.front() - 0.5, t.empty() ? 1 : t.front() + 0.5}
                                                        : Axis{t.front(), t.back()};
  // Speed axis: the truth and the estimate after the first second, without
  // its outermost 1 % (shown on the edge, marked); never forced to hold 0.
  std::vector<double> speeds;
  for (size_t i = 0; i < t.size(); ++i) {
    if (std::isfinite(truth[i])) speeds.push_back(truth[i]);
    if (t[i] >= settle || t.back() < settle) speeds.push_back(est[i]);
  }
  const double room = legend_height(3) + 14;  // a legend has up to three entries
  const Axis av = svg::with_headroom(svg::robust_range(speeds, any_truth ? 0.005 : 0.01, 0.02), kSpeedH, room);

  // Present flags, in bit order: one lane each under the panels.
  std::vector<const FlagStyle*> lanes;
  for (const FlagStyle& f : kFlagStyles)
    if (std::any_of(status.begin(), status.end(), [&](uint16_t s) { return s & f.flag; })) lanes.push_back(&f);

  const Panel speed{kTop, kSpeedH};
  const Panel error{speed.bottom() + kGap, any_truth ? kErrorH : 0};
  const double lanes_top = (any_truth ? error.bottom() : speed.bottom()) + kGap;
  const double lanes_h = lanes.empty() ? 14 : static_cast<double>(lanes.size()) * (kLaneH + kLaneGap);
  // The key of the lanes under the time axis: "NAME: meaning, N frames" each,
  // wrapped to the width.
  std::vector<std::pair<const FlagStyle*, std::string>> key;
  for (const FlagStyle* f : lanes) {
    size_t n = 0;
    for (size_t i = 0; i < std::size(kStatusFlags); ++i)
      if (kStatusFlags[i].flag == f->flag) n = counts.count[i];
    key.emplace_back(f, std::string(info_of(f->flag).name) + ": " + info_of(f->flag).meaning + ", " + frames_text(n));
  }
  std::vector<std::vector<size_t>> key_rows(key.empty() ? 0 : 1);
  double row_x = kX0;
  for (size_t i = 0; i < key.size(); ++i) {
    const double w = key_entry_width(key[i].second);
    if (row_x + w > kX1 && !key_rows.back().empty()) key_rows.emplace_back(), row_x = kX0;
    key_rows.back().push_back(i);
    row_x += w;
  }
  const double key_top = lanes_top + lanes_h + 46;
  const double height = key_top + 16.0 * static_cast<double>(key_rows.size()) + 6;

  std::string s = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + fmt("%.0f", kWidth) + "\" height=\"" +
                  fmt("%.0f", height) + "\" font-family=\"sans-serif\" font-size=\"12\">\n";
  s += "<rect width=\"100%\" height=\"100%\" fill=\"#fafafa\"/>\n";
  s += text(kWidth / 2, kTitleY, title, "middle", " font-size=\"15\"");
  s += text(kWidth / 2, kStatsY, stats_line(metrics, any_truth, counts), "middle");

  // Speed panel: flagged time shaded behind the lines, truth thick and light
  // underneath, the estimate thin on top.
  s += frame(speed, ax, av, "V (m/s)");
  auto shade = [&](const Panel& p) {
    std::string b;
    for (const FlagStyle* f : lanes)
      if (is_fault(f->flag))
        for (const auto& [a, e] : flag_runs(t, status, f->flag, ax))
          b += rect(ax.map(a, kX0, kX1), p.top, ax.map(e, kX0, kX1), p.bottom(), f->colour, 0.16);
    return b;
  };
  s += shade(speed);
  const Line truth_line = any_truth ? line(t, truth, ax, av, speed, kTruthColour, 4.5) : Line{};
  s += truth_line.svg;
  const Line est_line = line(t, est, ax, av, speed, kEstimateColour, 1.3);
  s += est_line.svg;
  std::vector<std::pair<std::string, std::string>> speed_legend;
  if (any_truth) speed_legend.emplace_back(sample_line(kTruthColour, 4.5), "ground truth V");
  speed_legend.emplace_back(sample_line(kEstimateColour, 1.3), "estimate V_est");
  if (est_line.clipped)
    speed_legend.emplace_back(sample_triangle(kEstimateColour),
                              frames_text(est_line.clipped) + " beyond the axis, " + beyond_text(est_line, "%.3g"));
  s += legend(speed, speed_legend, {&truth_line, &est_line});

  if (any_truth) {
    // Error panel: scaled on the errors after the first second (as the
    // paper's Fig. 4); the start-up frames beyond it are drawn on the edge and marked.
    std::vector<double> settled;
    for (size_t i = 0; i < err.size(); ++i)
      if (t[i] >= settle || t.back() < settle) settled.push_back(err[i]);
    const Axis ae = svg::with_headroom(svg::including(svg::robust_range(settled, 0, 0.002), 0.0), kErrorH, room);
    s += frame(error, ax, ae, "V_est - V (m/s)");
    s += shade(error);
    const Line err_line = line(t, err, ax, ae, error, kErrorColour, 1.2);
    s += err_line.svg;
    std::vector<std::pair<std::string, std::string>> error_legend{{sample_line(kErrorColour, 1.2), "error V_est - V"}};
    if (err_line.clipped)
      error_legend.emplace_back(sample_triangle(kErrorColour),
                                frames_text(err_line.clipped) + " beyond the axis (scaled after " +
                                    fmt("%.0f s", settle) + "), " + beyond_text(err_line, "%+.3g"));
    if (metrics.after_count && std::isfinite(metrics.worst_after)) {
      // Where it went most wrong after the start.
      size_t worst = 0;
      for (size_t i = 0; i < t.size(); ++i)
        if (std::fabs(t[i] - metrics.worst_after_t) < std::fabs(t[worst] - metrics.worst_after_t)) worst = i;
      const double wx = ax.map(t[worst], kX0, kX1);
      const double wy = ae.map(std::min(std::max(err[worst], ae.lo), ae.hi), error.bottom(), error.top);
      s += "<circle cx=\"" + px(wx) + "\" cy=\"" + px(wy) + "\" r=\"5\" fill=\"none\" stroke=\"#000\"/>\n";
      error_legend.emplace_back("<circle cx=\"12\" cy=\"0\" r=\"5\" fill=\"none\" stroke=\"#000\"/>",
                                "worst after " + fmt("%.0f s", settle) + ": " + fmt("%+.3g m/s", err[worst]) +
                                    fmt(" at %.2f s", t[worst]));
    }
    s += legend(error, error_legend, {&err_line});
  }

  // Flag lanes: when each flag was raised, with its name and meaning.
  if (lanes.empty()) {
    s += text(kX0, lanes_top + 10, "no status flag raised", "start", " fill=\"#555\"");
  } else {
    for (size_t k = 0; k < lanes.size(); ++k) {
      const FlagStyle& f = *lanes[k];
      const double y = lanes_top + static_cast<double>(k) * (kLaneH + kLaneGap);
      s += rect(kX0, y, kX1, y + kLaneH, "#eeeeee", 1.0);
      for (const auto& [a, e] : flag_runs(t, status, f.flag, ax))
        s += rect(ax.map(a, kX0, kX1), y, ax.map(e, kX0, kX1), y + kLaneH, f.colour, 0.95);
      s += text(kX0 - 6, y + kLaneH - 1, info_of(f.flag).name, "end", " font-size=\"10\"");
    }
  }
  const double axis_y = lanes_top + lanes_h + 14;
  for (const svg::Tick& k : svg::ticks(ax, kX1 - kX0, true)) s += text(ax.map(k.value, kX0, kX1), axis_y, k.label, "middle");
  s += text(kWidth / 2, axis_y + 17, "time (s)", "middle");
  for (size_t r = 0; r < key_rows.size(); ++r) {
    double x = kX0;
    const double y = key_top + 16.0 * static_cast<double>(r);
    for (size_t i : key_rows[r]) {
      s += rect(x, y - 9, x + 10, y + 1, key[i].first->colour, 0.95);
      s += text(x + 14, y, key[i].second, "start", " font-size=\"11\"");
      x += key_entry_width(key[i].second);
    }
  }
  s += "</svg>\n";
  return s;
}

void write_track_svg(const std::string& path, const std::vector<TrackPoint>& track, const std::string& title) {
  write_file(path, track_svg(track, title), "the plot");
}

}  // namespace lumavel::host
