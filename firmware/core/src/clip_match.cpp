#include "lumavel/core/clip_match.hpp"

namespace lumavel {

void clip_stats(const ImageView& in, ClipStats& s) {
  s = ClipStats{0, static_cast<uint32_t>(in.width) * in.height, 0};
  for (uint16_t y = 0; y < in.height; ++y) {
    const uint8_t* row = in.pixels + static_cast<uint32_t>(y) * in.stride;
    uint32_t sum = 0;  // a row: at most 65535 x 255 < 2^24
    for (uint16_t x = 0; x < in.width; ++x) {
      sum += row[x];
      s.at_max += row[x] == 255;
    }
    s.sum += sum;
  }
}

void match_clip_ceilings(const ClipStats& s0, const ClipStats& s1, uint8_t ceiling[2]) {
  ceiling[0] = ceiling[1] = 255;
  if (s0.pixels == 0 || s1.pixels == 0) return;
  // Means in Q8 (at most 255 x 2^8 < 2^16).
  const uint64_t m0 = (s0.sum << 8) / s0.pixels, m1 = (s1.sum << 8) / s1.pixels;
  const bool cam1_brighter = m1 > m0;
  const uint64_t bright = cam1_brighter ? m1 : m0, dark = cam1_brighter ? m0 : m1;
  const ClipStats& sb = cam1_brighter ? s1 : s0;
  const ClipStats& sd = cam1_brighter ? s0 : s1;
  // shares compared without a division: at_max / pixels (< 2^32 each)
  if (bright == dark || uint64_t{sb.at_max} * sd.pixels <= kClipShareRatio * sd.at_max * sb.pixels) return;
  // 255 / g = 255 x dark / bright, rounded; below 255 since dark < bright.
  ceiling[cam1_brighter ? 0 : 1] = static_cast<uint8_t>((255 * dark + bright / 2) / bright);
}

void clamp_pixels(uint8_t* px, uint16_t width, uint16_t height, uint32_t stride, uint8_t ceiling) {
  if (ceiling == 255) return;
  for (uint16_t y = 0; y < height; ++y) {
    uint8_t* row = px + static_cast<uint32_t>(y) * stride;
    for (uint16_t x = 0; x < width; ++x)
      if (row[x] > ceiling) row[x] = ceiling;
  }
}

}  // namespace lumavel
