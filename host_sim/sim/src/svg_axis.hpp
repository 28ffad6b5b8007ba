// Small pieces of the hand-written SVG plots: number formatting, escaping,
// axis ranges that ignore outliers, and ticks whose labels never overlap.
#pragma once
#include <string>
#include <vector>

namespace lumavel::host::svg {

std::string fmt(const char* f, double v);
std::string escape(const std::string& text);

struct Axis {
  double lo = 0, hi = 1;
  double map(double v, double a, double b) const { return a + (v - lo) / (hi - lo) * (b - a); }
};

// A padded range over `values` (NaN and infinities skipped) that leaves out
// the `tail` fraction of outliers at each end (0: every value) and always
// spans at least `min_span`; {0, 1} when there is no value.
Axis robust_range(std::vector<double> values, double tail, double min_span);
// Raises the top of `a` so that the top `room` pixels of a `pixels` high
// panel stay above the data (room for a legend).
Axis with_headroom(Axis a, double pixels, double room);
// Widens `a` to hold `v` (with a little padding).
Axis including(Axis a, double v);

struct Tick {
  double value;
  std::string label;
};
// Ticks at 1, 2 or 5 times a power of ten, as many as fit `pixels` with
// their labels `gap` pixels apart (label width from a 7 px character;
// vertical axes pass the label height instead with `horizontal` false).
std::vector<Tick> ticks(const Axis& a, double pixels, bool horizontal);

}  // namespace lumavel::host::svg
