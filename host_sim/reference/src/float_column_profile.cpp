// Twin of firmware/core/src/column_profile.cpp.
#include "lumavel/host/float_column_profile.hpp"

#include <cmath>
#include <vector>

#include "lumavel/core/estimator_params.hpp"
#include "lumavel/core/photometric_params.hpp"

namespace lumavel::host {

FloatColumnProfile float_column_profile(const FloatColumnBand& band, const uint8_t* img, int width, int height,
                                        bool radial) {
  FloatColumnProfile p;
  p.sum = Eigen::VectorXd::Zero(width);
  for (int y = 0; y < height; ++y)
    for (int u = 0; u < width; ++u) p.sum[u] += band.row_weight(y, u) * img[y * width + u];
  p.radial = radial && !band.banded && height >= 2;
  if (p.radial) {
    // The core's rings (column_profile.hpp): from the top and bottom edges
    // in, edge k at round((k + 1) H / (2 rings)), the last the middle rows;
    // each ring's rows weighed by their mean y^2.
    p.sum_y2 = Eigen::VectorXd::Zero(width);
    const int rings = params::kMatchRadialRings;
    int outer = 0;
    for (int k = 0; k < rings; ++k) {
      const bool middle = k == rings - 1;
      const int inner = middle ? height / 2 : (height * (k + 1) + rings) / (2 * rings);
      std::vector<int> rows;
      for (int y = outer; y < (middle ? height - outer : inner); ++y) rows.push_back(y);
      if (!middle)
        for (int y = height - inner; y < height - outer; ++y) rows.push_back(y);
      double c = 0;
      for (const int y : rows) c += std::pow(static_cast<double>(2 * y + 1 - height) / width, 2);
      if (!rows.empty()) c /= static_cast<double>(rows.size());
      for (const int y : rows)
        for (int u = 0; u < width; ++u) p.sum_y2[u] += c * img[y * width + u];
      p.rows_y2 += c * static_cast<double>(rows.size());
      outer = inner;
    }
  }
  if (!band.banded && height >= 2) {
    p.edge = Eigen::VectorXd::Zero(width);
    const uint8_t* top = img;
    const uint8_t* bottom = img + (height - 1) * width;
    for (int u = 0; u < width; ++u) {
      const double at_edges = height >= 4 ? 1.5 * (top[u] + bottom[u]) - 0.5 * (top[u + width] + bottom[u - width])
                                          : top[u] + bottom[u];
      p.edge[u] = 0.5 * height * at_edges - p.sum[u];
    }
  }
  for (int y = 0; y < height; y += params::kClipRowStep)
    for (int u = 0; u < width; ++u) {
      const uint8_t v = img[y * width + u];
      p.clipped += (v == 0 || v == 255);
      p.clip_sampled += 1;
    }
  return p;
}

bool float_same_textured_profile(const FloatColumnProfile& a, const FloatColumnProfile& b,
                                 const FloatColumnBand& band) {
  // Same images, same row weights: equal exactly where the core's sums are.
  // Flat: every sum in proportion to its rows (exact products: 23 x 16 bits).
  const Eigen::VectorXd& rows = band.rows;
  return a.sum == b.sum && (a.sum.array() * rows[0] != rows.array() * a.sum[0]).any();
}

}  // namespace lumavel::host
