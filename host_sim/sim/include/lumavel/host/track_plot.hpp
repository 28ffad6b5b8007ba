// Hand-written SVG of an estimate track, like the paper's Fig. 4 / Fig. 7,
// made to answer "how good, where did it go wrong, and why": E, RMS and the
// worst error on top; estimate (thin) over ground truth (thick, light) on an
// axis that fits the data; the error below, scaled after the first second
// with what falls beyond the axis marked; flagged frames shaded in the
// panels and laid out per flag in lanes underneath.
#pragma once
#include <string>
#include <vector>

#include "lumavel/host/run_metrics.hpp"

namespace lumavel::host {

// SVG text. Without ground truth there is one panel (the estimate) and no
// error figures.
std::string track_svg(const std::vector<TrackPoint>& track, const std::string& title);

// Writes track_svg() to `path`; throws std::runtime_error naming the file.
void write_track_svg(const std::string& path, const std::vector<TrackPoint>& track, const std::string& title);

}  // namespace lumavel::host
