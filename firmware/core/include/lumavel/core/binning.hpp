// Integer area averaging from a sensor frame to the working resolution:
// each output pixel is the overlap-weighted mean of the input pixels it
// covers (exact rational weights, rounded once). Works for any ratio >= 1.
#pragma once
#include <cstdint>

namespace lumavel {

struct ImageView {
  const uint8_t* pixels;
  uint16_t width;
  uint16_t height;
  uint32_t stride;  // bytes between rows
};

// The largest frame bin_area takes, in pixels (4096x4096): 255 * in.width *
// in.height must fit its 32-bit sums.
constexpr uint32_t kMaxBinPixels = uint32_t{1} << 24;

// dst is out_w * out_h bytes. Requires out_w <= in.width, out_h <= in.height,
// out_w <= kMaxColumns (limits.hpp), in.stride >= in.width and
// in.width * in.height <= kMaxBinPixels. False (dst untouched) if the sizes
// do not allow binning.
bool bin_area(const ImageView& in, uint8_t* dst, uint16_t out_w, uint16_t out_h);

}  // namespace lumavel
