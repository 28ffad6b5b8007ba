// Column sums taken as the rows arrive: a camera that delivers its frame row
// by row (DMA per line) needs no frame buffer. add_row() for rows 0 ..
// height-1 in order, then profile() is the same, bit for bit, as
// column_profile() of the whole frame (the sums, the edge rows of the
// rotation term, the clipped-pixel count), band or not. It costs one
// ColumnProfile (its sums are the accumulators) instead of width x height
// bytes: 40x30, two cameras, 2 400 B of frames -> about 700 B.
#pragma once
#include <cstdint>

#include "lumavel/core/column_profile.hpp"

namespace lumavel {

class ColumnStream {
 public:
  // A new frame of width x height (validated by the estimator's
  // configuration); band as for column_profile (nullptr: all rows).
  void start(uint16_t width, uint16_t height, const ColumnBand* band);
  // Row y (0 = top) of `width` pixels. Rows must come in order, each once;
  // a row out of order is ignored and the frame reported incomplete.
  void add_row(const uint8_t* row, uint16_t y);
  // Every row arrived in order.
  bool complete() const { return ok_ && next_ == height_; }
  // The frame's profile; valid once complete().
  ColumnProfile& profile() { return p_; }

 private:
  ColumnProfile p_{};
  const ColumnBand* band_ = nullptr;
  uint16_t height_ = 0;
  uint16_t next_ = 0;
  bool ok_ = false;
};

}  // namespace lumavel
