#include "lumavel/core/column_stream.hpp"

#include "lumavel/core/estimator_params.hpp"

namespace lumavel {

void ColumnStream::start(uint16_t width, uint16_t height, const ColumnBand* band) {
  band_ = kBandColumns > 1 ? band : nullptr;  // a line-scan build keeps no band
  height_ = height;
  next_ = 0;
  ok_ = true;
  p_.width = width;
  p_.q8 = band_ != nullptr;
  p_.plain_x256 = false;
  p_.edges = band_ == nullptr && kBandColumns > 1 && height >= 2;
  p_.clipped = 0;
  p_.clip_sampled = static_cast<uint32_t>((height + params::kClipRowStep - 1) / params::kClipRowStep) * width;
  for (uint16_t u = 0; u < width; ++u) p_.sum[u] = 0;
  for (uint16_t u = 0; u < width && u < kBandColumns; ++u) p_.edge4[u] = 0;
}

void ColumnStream::add_row(const uint8_t* row, uint16_t y) {
  if (!ok_ || y != next_ || y >= height_) {
    ok_ = false;
    return;
  }
  ++next_;
  const uint16_t width = p_.width;
  if (band_ == nullptr) {
    for (uint16_t u = 0; u < width; ++u) p_.sum[u] = static_cast<ColumnSum>(p_.sum[u] + row[u]);
  } else {
    // Q8: whole rows inside the band, its two boundary rows by edge_q8 (column_profile's to_band_q8).
    for (uint16_t u = 0; u < width; ++u) {
      const uint16_t first = band_->first[u];
      int32_t w = 0;
      if (y >= first && y < height_ - first) w = 256;
      else if (first > 0 && (y == first - 1 || y == height_ - first)) w = band_->edge_q8[u];
      p_.sum[u] = static_cast<ColumnSum>(p_.sum[u] + w * row[u]);
    }
  }
  // The edge rows' part of 4 E (column_profile.hpp): 3 (r0 + rb) - r1 - rb1,
  // or 2 (r0 + rb) below 4 rows; -4 sum is added at the last row.
  if (p_.edges) {
    const uint16_t last = static_cast<uint16_t>(height_ - 1);
    const bool four = height_ >= 4;
    int32_t k = 0;
    if (y == 0 || y == last) k = four ? 3 : 2;
    else if (four && (y == 1 || y == last - 1)) k = -1;
    if (k != 0)
      for (uint16_t u = 0; u < width && u < kBandColumns; ++u) p_.edge4[u] += k * row[u];
    if (y == last)
      for (uint16_t u = 0; u < width && u < kBandColumns; ++u)
        p_.edge4[u] = int32_t{height_} * p_.edge4[u] - 4 * int32_t{p_.sum[u]};
  }
  if (y % params::kClipRowStep == 0)
    for (uint16_t u = 0; u < width; ++u) p_.clipped += static_cast<uint32_t>(static_cast<uint8_t>(row[u] + 1u) <= 1u);
}

}  // namespace lumavel
