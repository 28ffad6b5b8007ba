// Small scenes for the renderer tests, built in code (no YAML).
#pragma once
#include <string>
#include <vector>

#include "lumavel/host/render/scenario.hpp"

namespace lumavel::host::render::test {

// Rig at rest at the origin (heading 0), a 1-segment straight trajectory of
// `speed`, no planes; background 0.
Scenario empty_scenario(int width, int height, double speed = 0);

// empty_scenario turning all the time: an arc left (R 4 m, 0.5 -> 1.5 m/s,
// smooth), then right (R 6 m, 1 m/s), each half of `duration_s`.
Scenario turning_pass(int width, int height, double duration_s);

// A vertical plane parallel to the x axis at y = `y`, spanning x in [x0, x1]
// and z in [z0, z1]; `from`/`to` ordered so it reads upright from the origin.
PlaneSpec wall_at(double y, double x0, double x1, double z0, double z1, const PatternSpec& p);

PatternSpec uniform(double v);
PatternSpec checker(double square, double low, double high);

// Fresh empty folder under the system temp dir (removed first if present).
// Radiance (before noise and rounding) of frame 0 of camera `cam`.
std::vector<double> radiance(const Scenario& s, int cam = 0);
// With a plane of 255 on background 0 covering a row from the left up to a
// vertical edge, the edge's u is the covered length of the row - 0.5 (box
// filtering makes this exact).
double edge_u_from_left(const std::vector<double>& img, int w, int row);

std::string temp_dir(const std::string& name);
std::string read_text(const std::string& path);
std::string first_line(const std::string& path);

}  // namespace lumavel::host::render::test
