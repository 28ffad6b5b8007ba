// Lens tables as the firmware takes them (EstimatorConfig::edge_offsets):
// for each column edge u = 0..width, the correction (EdgeOffsetQ15, rad)
// from the pinhole edge the firmware computes itself to the edge through the
// lens. The one builder of such tables on the host (the engines' settings,
// the device setup, the synthetic stream's barrel lens).
#pragma once
#include <cstdint>
#include <vector>

#include "lumavel/core/config.hpp"
#include "lumavel/units/fixed.hpp"

namespace lumavel::host {

struct LensTable {
  std::vector<EdgeOffsetQ15> offsets;  // width + 1 corrections; empty when one does not fit
  int bad_edge = -1;                   // else the first edge whose correction is outside [-1, 1) rad,
  double bad_offset_rad = 0;           // and that correction
};

// `edges`: the lens's column edges (width + 1, Q3.28 rad). Each correction
// is edges[u] minus the firmware's pinhole edge of `g` (pinhole_column_edges,
// the same integer atan, so the device rebuilds edges[u] to within half a
// Q15 step), rounded half away from zero.
LensTable lens_table(const CameraGeometry& g, uint16_t width, const std::vector<AngleQ28>& edges);

}  // namespace lumavel::host
