// The SVG plot: panels, lines, gaps in the truth, and bounded size.
#include <cmath>
#include <string>

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
