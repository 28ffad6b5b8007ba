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

// Both cameras delivered the same textured image (one frame twice: a wiring
// or driver fault): every column sum equal, and not all columns alike. Two
// real cameras never give this: their independent pixel noise (and, for a
// rig that is not perfectly aligned, their different views) makes some sum
// differ, however far and weak the scene; a far scene is low texture, which
// rms(F1 - F0) measures. A flat profile is left to low texture as well.
bool same_textured_profile(const ColumnProfile& a, const ColumnProfile& b);

}  // namespace lumavel
