// Column sums of one working-resolution frame: the only per-pixel work.
#pragma once
#include <cstdint>

#include "lumavel/core/limits.hpp"

namespace lumavel {

struct ColumnProfile {
  uint16_t sum[kMaxColumns];  // sum over rows, <= 255 * kMaxRows < 2^15
  uint16_t width;
  uint32_t clipped;           // pixels at 0 or 255 among the sampled rows
  uint32_t clip_sampled;      // pixels inspected for clipping (every 8th row)
};

// Also counts clipped pixels (0 or 255) on every 8th row for the saturation flag.
void column_profile(const uint8_t* pixels, uint16_t width, uint16_t height, uint16_t stride,
                    ColumnProfile& out);

}  // namespace lumavel
