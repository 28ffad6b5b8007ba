// Area averaging with exact integer overlaps: input pixel x spans
// [x*out_w, (x+1)*out_w) and output pixel X spans [X*in_w, (X+1)*in_w) on a
// common integer axis, so every overlap is an integer and the weights of one
// output pixel sum to in_w * in_h.
#include "lumavel/core/binning.hpp"

#include "lumavel/core/limits.hpp"

namespace lumavel {
namespace {

// Adds one input row, horizontally binned and weighted by wy, into acc.
void add_row(const uint8_t* row, uint16_t in_w, uint16_t out_w, uint32_t wy, uint32_t* acc) {
  uint32_t a = 0;  // left edge of input pixel x on the common axis
  uint16_t X = 0;
  uint32_t edge = in_w;  // right edge of output pixel X
  for (uint16_t x = 0; x < in_w; ++x, a += out_w) {
    const uint32_t p = uint32_t{row[x]} * wy;
    const uint32_t b = a + out_w;
    if (b <= edge) {
      acc[X] += p * out_w;
    } else {
      acc[X] += p * (edge - a);
      ++X;
      acc[X] += p * (b - edge);
      edge += in_w;
    }
    if (b == edge) {
      ++X;
      edge += in_w;
    }
  }
}

}  // namespace

bool bin_area(const ImageView& in, uint8_t* dst, uint16_t out_w, uint16_t out_h) {
  if (in.pixels == nullptr || dst == nullptr) return false;
  if (out_w == 0 || out_h == 0 || out_w > in.width || out_h > in.height) return false;
  if (out_w > kMaxColumns || in.stride < in.width) return false;
  // 255 * in_w * in_h must fit 32 bits.
  if (uint64_t{in.width} * in.height > kMaxBinPixels) return false;
  const uint32_t denom = uint32_t{in.width} * in.height;
  uint32_t acc[kMaxColumns];
  for (uint16_t Y = 0; Y < out_h; ++Y) {
    for (uint16_t X = 0; X < out_w; ++X) acc[X] = 0;
    const uint32_t top = uint32_t{Y} * in.height;  // output row Y on the common axis
    const uint32_t bottom = top + in.height;
    for (uint32_t y = top / out_h; y < in.height && y * out_h < bottom; ++y) {
      const uint32_t a = y * out_h, b = a + out_h;
      const uint32_t lo = a > top ? a : top, hi = b < bottom ? b : bottom;
      if (hi <= lo) continue;
      add_row(in.pixels + y * in.stride, in.width, out_w, hi - lo, acc);
    }
    for (uint16_t X = 0; X < out_w; ++X)
      dst[uint32_t{Y} * out_w + X] = static_cast<uint8_t>((acc[X] + denom / 2) / denom);
  }
  return true;
}

}  // namespace lumavel
