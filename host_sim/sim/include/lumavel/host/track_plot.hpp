// Hand-written SVG of an estimate track, like the paper's Fig. 4 / Fig. 7:
// estimate and ground truth against time on top, the error below.
#pragma once
#include <string>
#include <vector>

#include "lumavel/host/run_metrics.hpp"

namespace lumavel::host {

// SVG text. Without ground truth there is one panel (the estimate).
std::string track_svg(const std::vector<TrackPoint>& track, const std::string& title);

// Writes track_svg() to `path`; throws std::runtime_error naming the file.
void write_track_svg(const std::string& path, const std::vector<TrackPoint>& track, const std::string& title);

}  // namespace lumavel::host
