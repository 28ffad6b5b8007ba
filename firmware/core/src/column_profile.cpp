#include "lumavel/core/column_profile.hpp"

#include <cstdint>
#include <cstring>

#include "lumavel/core/estimator_params.hpp"
#if defined(__ARM_FEATURE_SIMD32)
#include <arm_acle.h>
#endif

namespace lumavel {
namespace {

// Rows whose clipped pixels are counted: one in eight (cost 1/8 of a pass).
constexpr uint16_t kClipRowStep = params::kClipRowStep;

uint32_t load_word(const uint8_t* p) {
  uint32_t w;
  std::memcpy(&w, p, sizeof w);  // one LDR where unaligned loads are allowed
  return w;
}

// Clipped (0x00 or 0xFF) bytes among the 4 of w, without branches: a byte is
// clipped iff its 8 bits are equal, i.e. iff (b ^ b >> 1) & 0x7F == 0.
uint32_t clipped_in_word(uint32_t w) {
  const uint32_t y = (w ^ (w >> 1)) & 0x7F7F7F7Fu;
  const uint32_t nonzero = ((y + 0x7F7F7F7Fu) | y) & 0x80808080u;  // bit 7: byte of y != 0
  return 4u - (((nonzero >> 7) * 0x01010101u) >> 24);
}

}  // namespace

void column_profile(const uint8_t* pixels, uint16_t width, uint16_t height, uint16_t stride,
                    ColumnProfile& out) {
  out.width = width;
  // Four columns at a time, down all rows: two 16-bit lanes per register
  // (255 * 128 < 2^16), so each pixel costs about one load share and one add.
  // Word-aligned rows take the aligned path (one LDR per four pixels).
  const bool aligned = ((reinterpret_cast<uintptr_t>(pixels) | stride) & 3u) == 0;
  uint16_t u = 0;
  const uint32_t rows_bytes = uint32_t{height} * stride;
  for (; u + 4 <= width; u += 4) {
    uint32_t even = 0, odd = 0;
    const uint8_t* p = pixels + u;
    const uint8_t* const end = p + rows_bytes;
    if (aligned) {
#if defined(__ARM_FEATURE_SIMD32)
      // Cortex-M4/M7: UXTAB16 adds bytes 0 and 2 (or 1 and 3, rotated) to two 16-bit lanes.
      for (; p != end; p += stride) {
        const uint32_t w = load_word(static_cast<const uint8_t*>(__builtin_assume_aligned(p, 4)));
        even = __uxtab16(even, w);
        odd = __uxtab16(odd, (w >> 8) | (w << 24));  // UXTAB16 with ROR #8
      }
#else
      for (; p != end; p += stride) {
        const uint32_t w = load_word(static_cast<const uint8_t*>(__builtin_assume_aligned(p, 4)));
        even += w & 0x00FF00FFu;
        odd += (w >> 8) & 0x00FF00FFu;
      }
#endif
    } else {
      for (; p != end; p += stride) {
        const uint32_t w = load_word(p);
        even += w & 0x00FF00FFu;
        odd += (w >> 8) & 0x00FF00FFu;
      }
    }
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
    uint16_t c = 0;
    if (aligned) {
      for (; c + 4 <= width; c = static_cast<uint16_t>(c + 4))
        clipped += clipped_in_word(load_word(static_cast<const uint8_t*>(__builtin_assume_aligned(p + c, 4))));
    } else {
      for (; c + 4 <= width; c = static_cast<uint16_t>(c + 4)) clipped += clipped_in_word(load_word(p + c));
    }
    for (; c < width; ++c) clipped += static_cast<uint32_t>(static_cast<uint8_t>(p[c] + 1u) <= 1u);
  }
  out.clipped = clipped;
  out.clip_sampled = static_cast<uint32_t>((height + kClipRowStep - 1) / kClipRowStep) * width;
}

bool same_textured_profile(const ColumnProfile& a, const ColumnProfile& b) {
  if (a.width != b.width || a.width == 0) return false;
  bool flat = true;
  for (uint16_t u = 0; u < a.width; ++u) {
    if (a.sum[u] != b.sum[u]) return false;
    flat = flat && a.sum[u] == a.sum[0];
  }
  return !flat;
}

}  // namespace lumavel
