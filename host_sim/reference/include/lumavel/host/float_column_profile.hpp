// The double twin of firmware/core/column_profile.hpp: each column's sum over
// the rows its band gives it, the clipped-pixel count beside it, and the
// duplicated-frame test on two profiles.
#pragma once
#include <Eigen/Dense>
#include <cstdint>

#include "lumavel/host/float_column_band.hpp"

namespace lumavel::host {

struct FloatColumnProfile {
  Eigen::VectorXd sum;      // per column: its row-weighted sum (FloatColumnBand::row_weight)
  // Without a band: E = (H/2)(edge rows' value at the image's edge) - sum, per
  // column (the core's edge4 / 4); empty with a band or on a line scan.
  Eigen::VectorXd edge;
  // With `radial` (no band): each column weighted by y^2 per row group, and
  // a uniform image's value (the core's sum_y2 / 256, rows_y2_q8 / 256).
  bool radial = false;
  Eigen::VectorXd sum_y2;
  double rows_y2 = 0;
  double clipped = 0;       // pixels at 0 or 255 among the sampled rows
  double clip_sampled = 0;  // pixels inspected for clipping (every kClipRowStep-th row)
};

// img: width x height, packed.
FloatColumnProfile float_column_profile(const FloatColumnBand& band, const uint8_t* img, int width, int height,
                                        bool radial = false);

// Twin of same_textured_profile: every column sum equal, and not every sum
// in proportion to the rows it sums (read the core's header for why two real
// cameras never give this).
bool float_same_textured_profile(const FloatColumnProfile& a, const FloatColumnProfile& b,
                                 const FloatColumnBand& band);

}  // namespace lumavel::host
