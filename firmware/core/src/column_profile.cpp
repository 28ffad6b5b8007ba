#include "lumavel/core/column_profile.hpp"

#include <cstring>

namespace lumavel {
namespace {

// Rows whose clipped pixels are counted: one in eight (cost 1/8 of a pass).
constexpr uint16_t kClipRowStep = 8;

uint32_t load_word(const uint8_t* p) {
  uint32_t w;
  std::memcpy(&w, p, sizeof w);  // one LDR where unaligned loads are allowed
  return w;
}

}  // namespace

void column_profile(const uint8_t* pixels, uint16_t width, uint16_t height, uint16_t stride,
                    ColumnProfile& out) {
  out.width = width;
  // Four columns at a time, down all rows: two 16-bit lanes per register
  // (255 * 128 < 2^16), so each pixel costs about one load share and one add.
  uint16_t u = 0;
  for (; u + 4 <= width; u += 4) {
    uint32_t even = 0, odd = 0;
    const uint8_t* p = pixels + u;
    for (uint16_t r = 0; r < height; ++r, p += stride) {
      const uint32_t w = load_word(p);
      even += w & 0x00FF00FFu;
      odd += (w >> 8) & 0x00FF00FFu;
    }
    // Byte order of the load decides which lane is which column.
    uint8_t probe[4] = {1, 0, 0, 0};
    const bool little = load_word(probe) == 1u;
    const uint16_t lo_e = static_cast<uint16_t>(even & 0xFFFFu), hi_e = static_cast<uint16_t>(even >> 16);
    const uint16_t lo_o = static_cast<uint16_t>(odd & 0xFFFFu), hi_o = static_cast<uint16_t>(odd >> 16);
    if (little) {
      out.sum[u] = lo_e; out.sum[u + 1] = lo_o; out.sum[u + 2] = hi_e; out.sum[u + 3] = hi_o;
    } else {
      out.sum[u] = hi_o; out.sum[u + 1] = hi_e; out.sum[u + 2] = lo_o; out.sum[u + 3] = lo_e;
    }
  }
  for (; u < width; ++u) {
    uint32_t s = 0;
    const uint8_t* p = pixels + u;
    for (uint16_t r = 0; r < height; ++r, p += stride) s += *p;
    out.sum[u] = static_cast<uint16_t>(s);
  }
  uint32_t clipped = 0;
  for (uint16_t r = 0; r < height; r = static_cast<uint16_t>(r + kClipRowStep)) {
    const uint8_t* p = pixels + uint32_t{r} * stride;
    for (uint16_t c = 0; c < width; ++c) clipped += static_cast<uint32_t>(static_cast<uint8_t>(p[c] + 1u) <= 1u);
  }
  out.clipped = clipped;
  out.clip_sampled = static_cast<uint32_t>((height + kClipRowStep - 1) / kClipRowStep) * width;
}

}  // namespace lumavel
