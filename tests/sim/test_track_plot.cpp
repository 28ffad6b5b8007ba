// The SVG plot: panels, lines, gaps in the truth, and bounded size.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>

#include "lumavel/core/status.hpp"
#include "lumavel/host/track_plot.hpp"
// CppUTest last: its leak-detector macros redefine new.
#include "CppUTest/TestHarness.h"

using namespace lumavel::host;

namespace {
size_t count(const std::string& s, const std::string& what) {
  size_t n = 0;
  for (size_t p = s.find(what); p != std::string::npos; p = s.find(what, p + 1)) ++n;
  return n;
}
std::vector<TrackPoint> track(size_t n, bool truth) {
  std::vector<TrackPoint> t;
  for (size_t i = 0; i < n; ++i) {
    const double v = std::sin(0.001 * static_cast<double>(i));
    t.push_back({i * 10000000ull, v + 0.05, truth ? v : std::nan("")});
  }
  return t;
}
}  // namespace

TEST_GROUP(TrackPlot) {};

TEST(TrackPlot, EstimateTruthAndErrorPanels) {
  const std::string svg = track_svg(track(500, true), "run <a&b>");
  CHECK(svg.rfind("<svg xmlns=\"http://www.w3.org/2000/svg\"", 0) == 0);
  CHECK(svg.find("</svg>") != std::string::npos);
  LONGS_EQUAL(3, count(svg, "<polyline"));  // truth, estimate, error
  STRCMP_CONTAINS("V_est - V (m/s)", svg.c_str());
  STRCMP_CONTAINS("run &lt;a&amp;b&gt;", svg.c_str());
  STRCMP_CONTAINS("time (s)", svg.c_str());
}

// The title is the recording's name: one with a control character or a byte
// that is no UTF-8 (a folder named 'e<ESC>[2Jrec', or 'caf\xE9' in Latin-1)
// made an SVG that is not well-formed XML, which no browser opens.
TEST(TrackPlot, ATitleXmlCannotHoldIsShownEscaped) {
  const std::string svg = track_svg(track(50, true), "e\x1b[2Jrec caf\xE9 <&>");
  STRCMP_CONTAINS("e\\x1B[2Jrec caf\\xE9 &lt;&amp;&gt;", svg.c_str());
  CHECK(svg.find('\x1b') == std::string::npos);
  CHECK(svg.find('\xE9') == std::string::npos);
}

TEST(TrackPlot, WithoutTruthOnlyTheEstimate) {
  const std::string svg = track_svg(track(500, false), "x");
  LONGS_EQUAL(1, count(svg, "<polyline"));
  CHECK(svg.find("V_est - V") == std::string::npos);
}

TEST(TrackPlot, MissingTruthBreaksTheLine) {
  std::vector<TrackPoint> t = track(500, true);
  for (size_t i = 200; i < 260; ++i) t[i].v_true = std::nan("");
  LONGS_EQUAL(5, count(track_svg(t, "x"), "<polyline"));  // truth and error in two pieces each
}

TEST(TrackPlot, LongRunsAreDecimated) {
  const std::string svg = track_svg(track(200000, true), "x");
  CHECK(svg.size() < 200000);
}

TEST(TrackPlot, EmptyAndConstantTracksStillMakeAPicture) {
  CHECK(track_svg({}, "x").find("</svg>") != std::string::npos);
  std::vector<TrackPoint> flat = {{0, 1, 1}, {10, 1, 1}};
  CHECK(track_svg(flat, "x").find("nan") == std::string::npos);
  // Values a few ulps apart (a held V against a truth from interpolation):
  // once an endless tick loop that filled the memory.
  const double one = 1.0, next = std::nextafter(std::nextafter(1.0, 2.0), 2.0);
  std::vector<TrackPoint> ulps = {{0, 0, one}, {10000000, 0, next}, {20000000, 0, one}};
  const std::string svg = track_svg(ulps, "x");
  CHECK(svg.find("</svg>") != std::string::npos);
  CHECK(svg.size() < 20000);
}

namespace {
// Every <text> of an SVG with its x and y, for overlap checks.
struct Label {
  double x, y;
  std::string text;
};
std::vector<Label> labels(const std::string& svg) {
  std::vector<Label> out;
  for (size_t p = svg.find("<text x=\""); p != std::string::npos; p = svg.find("<text x=\"", p + 1)) {
    const double x = std::atof(svg.c_str() + p + 9);
    const size_t yq = svg.find("y=\"", p);
    const double y = std::atof(svg.c_str() + yq + 3);
    const size_t a = svg.find('>', p) + 1, b = svg.find("</text>", a);
    out.push_back({x, y, svg.substr(a, b - a)});
  }
  return out;
}
}  // namespace

// The plot says how good (E, RMS, worst) and has a legend with line samples.
TEST(TrackPlot, FiguresAndLegendWithSamples) {
  const std::string svg = track_svg(track(500, true), "x");
  STRCMP_CONTAINS(">E ", svg.c_str());
  STRCMP_CONTAINS("RMS ", svg.c_str());
  STRCMP_CONTAINS("worst |err| after 1 s", svg.c_str());
  STRCMP_CONTAINS(">ground truth V<", svg.c_str());
  STRCMP_CONTAINS(">estimate V_est<", svg.c_str());
  STRCMP_CONTAINS(">error V_est - V<", svg.c_str());
  CHECK(count(svg, "<line x1=\"0\" y1=\"0\" x2=\"24\"") >= 3);  // a line sample per series
  // The truth is drawn first, thick and light; the estimate thin on top.
  const size_t truth = svg.find("stroke=\"#9a9a9a\" stroke-width=\"4.5\""),
               est = svg.find("stroke=\"#0072B2\" stroke-width=\"1.3\"");
  CHECK(truth != std::string::npos && est != std::string::npos && truth < est);
}

// Flagged frames are shaded in the panels and named in a lane per flag.
TEST(TrackPlot, FlaggedFramesAreShadedAndNamed) {
  std::vector<TrackPoint> t = track(500, true);
  for (size_t i = 100; i < 150; ++i) t[i].status = lumavel::kStatusSaturated;
  t[300].status = lumavel::kStatusFrameGap;
  const std::string svg = track_svg(t, "x");
  STRCMP_CONTAINS(">SATURATED<", svg.c_str());
  STRCMP_CONTAINS(">SATURATED: saturated pixels or arithmetic, 50 frames<", svg.c_str());
  STRCMP_CONTAINS(">FRAME_GAP: frame gap, 1 frame<", svg.c_str());
  STRCMP_CONTAINS(">FRAME_GAP<", svg.c_str());
  STRCMP_CONTAINS("a fault flagged on 10 % of frames", svg.c_str());
  CHECK(count(svg, "fill=\"#CC79A7\" fill-opacity=\"0.16\"") == 2);  // one band in each panel
  CHECK(track_svg(track(500, true), "x").find("no status flag raised") != std::string::npos);
}

// The speed axis fits the data, not 0; what lies beyond an axis is marked
// and said, in both panels.
TEST(TrackPlot, AxesFitTheDataAndMarkWhatTheyClip) {
  std::vector<TrackPoint> t;
  for (size_t i = 0; i < 600; ++i) {
    const double v = 0.5 + 0.1 * static_cast<double>(i) / 600.0;
    t.push_back({i * 20000000ull, i < 5 ? 0.0 : v + 0.001, v});  // starts at 0, converges fast
  }
  t[400].v_est = 6.7;  // a spike
  const std::string svg = track_svg(t, "x");
  for (const Label& l : labels(svg))
    if (l.x < 104 && l.y < 300) CHECK_TEXT(l.text != "0.0" && l.text != "0.00", "the speed axis holds 0");
  STRCMP_CONTAINS("6 frames beyond the axis, down to 0, up to 6.7 m/s", svg.c_str());
  STRCMP_CONTAINS("5 frames beyond the axis (scaled after 1 s), down to -0.501 m/s", svg.c_str());
  CHECK(count(svg, "<path d=\"M") >= 2);  // the triangles on the edges
}

// Tick labels of large values never overlap.
TEST(TrackPlot, TickLabelsDoNotOverlap) {
  std::vector<TrackPoint> t;
  for (size_t i = 0; i < 1000; ++i) t.push_back({i * 3600000000000ull, 123456.0 * static_cast<double>(i), 0.0});
  const std::string svg = track_svg(t, "x");
  std::vector<Label> bottom;
  double lowest = 0;
  for (const Label& l : labels(svg)) lowest = std::max(lowest, l.y);
  for (const Label& l : labels(svg))
    if (l.text != "time (s)" && l.y > lowest - 30 && l.y < lowest) bottom.push_back(l);
  CHECK(bottom.size() >= 3);
  for (size_t i = 1; i < bottom.size(); ++i)
    CHECK_TEXT(bottom[i].x - bottom[i - 1].x > 3.5 * static_cast<double>(bottom[i].text.size() + bottom[i - 1].text.size()),
               (bottom[i - 1].text + " / " + bottom[i].text).c_str());
  std::vector<Label> left;
  for (const Label& l : labels(svg))
    if (l.x < 104 && l.x > 50) left.push_back(l);
  for (size_t i = 1; i < left.size(); ++i)
    if (std::fabs(left[i].x - left[i - 1].x) < 1) CHECK(std::fabs(left[i].y - left[i - 1].y) >= 14);
}

// One frame is a dot, not an empty plot.
TEST(TrackPlot, OneFrameIsDrawn) {
  const std::string svg = track_svg({{5000000000ull, 0.5, 0.52}}, "x");
  CHECK(count(svg, "<circle") >= 2);  // the estimate and the truth
  CHECK(svg.find("nan") == std::string::npos);
}

// CONVERGING and NO_TOF have lanes but are not faults: the figures line does
// not say "no frame flagged" over lanes that show flags.
TEST(TrackPlot, OnlyFaultsCountAsFlagged) {
  std::vector<TrackPoint> t = track(500, true);
  for (size_t i = 0; i < 30; ++i) t[i].status = lumavel::kStatusConverging | lumavel::kStatusNoTof;
  const std::string svg = track_svg(t, "x");
  STRCMP_CONTAINS(">CONVERGING<", svg.c_str());
  STRCMP_CONTAINS("no fault flagged", svg.c_str());
  CHECK(svg.find("no frame flagged") == std::string::npos);
}

// The key under the time axis: each entry starts after the previous one's
// words end (11 px text is about 6.3 px a character when rendered).
TEST(TrackPlot, KeyEntriesDoNotOverlap) {
  std::vector<TrackPoint> t = track(600, true);
  for (size_t i = 0; i < 54; ++i) t[i].status |= lumavel::kStatusConverging;
  for (size_t i = 100; i < 135; ++i) t[i].status |= lumavel::kStatusLowTexture;
  for (size_t i = 200; i < 300; ++i) t[i].status |= lumavel::kStatusSaturated;
  for (size_t i = 0; i < 142; ++i) t[i].status |= lumavel::kStatusNoTof;
  const std::string svg = track_svg(t, "x");
  std::vector<Label> key;
  for (const Label& l : labels(svg))
    if (l.text.find(" frames") != std::string::npos && l.text.find(": ") != std::string::npos) key.push_back(l);
  LONGS_EQUAL(4, key.size());
  for (size_t i = 1; i < key.size(); ++i)
    if (key[i].y == key[i - 1].y)
      CHECK_TEXT(key[i].x - key[i - 1].x >= 6.3 * static_cast<double>(key[i - 1].text.size()) + 14,
                 (key[i - 1].text + " / " + key[i].text).c_str());
}

// Points clipped at both edges in the same place get a triangle on each.
TEST(TrackPlot, ClippedBothWaysIsMarkedOnBothEdges) {
  std::vector<TrackPoint> t;
  for (size_t i = 0; i < 600; ++i) t.push_back({i * 16666667ull, 1.0 + 0.001 * std::sin(0.1 * static_cast<double>(i)), 1.0});
  t[0].v_est = 0;   // starts at 0: below the speed axis
  t[1].v_est = 5;   // overshoots: above it, one pixel column later
  const std::string svg = track_svg(t, "x");
  STRCMP_CONTAINS("2 frames beyond the axis, down to 0, up to 5 m/s", svg.c_str());
  LONGS_EQUAL(3, count(svg, "Z\" fill=\"#0072B2\""));  // a triangle on each edge, and the legend's
}
