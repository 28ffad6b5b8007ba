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

// dst is out_w * out_h bytes. Requires out_w <= in.width, out_h <= in.height,
// out_w <= kMaxColumns (limits.hpp), in.stride >= in.width and
// in.width * in.height <= 2^24. False (dst untouched) if the sizes do not
// allow binning.
bool bin_area(const ImageView& in, uint8_t* dst, uint16_t out_w, uint16_t out_h);

}  // namespace lumavel
