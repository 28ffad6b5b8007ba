#include "lumavel/host/lens_table.hpp"

#include "lumavel/core/kernel_bank.hpp"
#include "lumavel/units/si.hpp"

namespace lumavel::host {

LensTable lens_table(const CameraGeometry& g, uint16_t width, const std::vector<AngleQ28>& edges) {
  std::vector<AngleQ28> pin(size_t{width} + 1);
  pinhole_column_edges(g, width, pin.data());
  LensTable t;
  for (size_t u = 0; u < edges.size() && u < pin.size(); ++u) {
    const int64_t d = int64_t{edges[u]} - pin[u];  // Q28
    // Q28 -> Q15: exact in double, so this is round(ldexp(d, -13)).
    const int64_t q = fx::shr_round(d, fx::kAngleFrac - fx::kEdgeOffsetFrac);
    if (q < INT16_MIN || q > INT16_MAX) {
      t.offsets.clear();
      t.bad_edge = static_cast<int>(u);
      t.bad_offset_rad = si::from_q(d, fx::kAngleFrac);
      return t;
    }
    t.offsets.push_back(static_cast<EdgeOffsetQ15>(q));
  }
  return t;
}

}  // namespace lumavel::host
