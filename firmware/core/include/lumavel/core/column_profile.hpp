// Column sums of one working-resolution frame: the only per-pixel work.
#pragma once
#include <cstdint>
#include <type_traits>

#include "lumavel/core/limits.hpp"
#include "lumavel/core/photometric_params.hpp"

namespace lumavel {

// The rows each column sums: the elevation band that every column sees
// (built with the kernel tables, kernel_bank.hpp; one band for both cameras,
// so that one image on both gives equal sums). Column u sums rows
// first[u] .. height-1-first[u] whole, and rows first[u]-1 and height-first[u]
// with weight edge_q8[u] / 256 (none when first[u] == 0). A line scan
// (kMaxRows == 1) never bands: its arrays shrink to one entry.
constexpr int kBandColumns = kMaxRows > 1 ? kMaxColumns : 1;
struct ColumnBand {
  uint8_t first[kBandColumns];
  uint8_t edge_q8[kBandColumns];
};

// A line-scan build (no band) keeps 16-bit sums (255 * kMaxRows < 2^15):
// the blue pill's stack stays what it was.
using ColumnSum = std::conditional_t<(kBandColumns > 1), int32_t, int16_t>;

struct ColumnProfile {
  // Sums over rows: plain (<= 255 * kMaxRows < 2^15) without a band; with a
  // band (q8), row-weighted in Q8 (256 = one pixel of value 1, < 2^23).
  // Everything downstream is a ratio of two dot products of one profile, so
  // the scale cancels; plain sums keep the cheaper 32-bit products.
  ColumnSum sum[kMaxColumns];
  // Without a band, each column's edge rows against its sum, for the rotation
  // term's Leibniz correction (measurement.hpp): 4 E = H (3 r0 - r1 + 3 rb - rb1)
  // - 4 sum, r0/rb the top and bottom rows, r1/rb1 the next ones in (the
  // rows' value at the image's edge, extrapolated half a row; H < 4: the
  // edge rows alone, 2 H (r0 + rb) - 4 sum). |4 E| < 2^18. Valid when `edges`.
  int32_t edge4[kBandColumns];
  uint16_t width;
  bool q8;
  // q8 sums that are plain sums times 256 exactly (the photometric match's
  // mapping of twins): a core without a 64-bit multiply takes their dot
  // products on the plain sums, in 32-bit products (kernel_dot.hpp).
  bool plain_x256;
  bool edges;
  uint32_t clipped;           // pixels at 0 or 255 among the sampled rows
  uint32_t clip_sampled;      // pixels inspected for clipping (every 8th row)
};

// The rows in kMatchRadialRings rings from the top and bottom edges in:
// ring k the rows [edge[k-1], edge[k]) and their mirror images
// [H - edge[k], H - edge[k-1]) (edge[-1] = 0), the last ring the middle rows
// [edge[kRings-2], H - edge[kRings-2]); edge[k] = round((k + 1) H / (2 kRings)).
// Each weighed by its rows' mean y^2 (Q8, < 2^14); built once per geometry
// (kernel_bank.hpp): only for more than one row and no band.
constexpr int kRadialRings = params::kMatchRadialRings;
struct RadialRings {
  uint16_t height;
  uint16_t edge[kRadialRings - 1];
  int32_t weight_q8[kRadialRings];
  int32_t rows_y2_q8;  // a uniform image of value 1: sum of weight x rows
};
RadialRings radial_rings(uint16_t width, uint16_t height);

// Each column's sum weighted by y^2 (y = (2r + 1 - H) / W the row's centre,
// in units of half the width), each ring of rows at its mean y^2, in Q8 (a
// uniform image of value 1 sums to rows_y2_q8 in every column; < 2^30: y^2
// < 64, 255 * kMaxRows < 2^15): the photometric match's radial vignetting
// (photometric_match.hpp), for cam1 only. Apart from ColumnProfile so that
// a device that streams its rows (column_stream.hpp) does not carry it.
struct RadialSums {
  int32_t sum_y2[kBandColumns];
  int32_t rows_y2_q8;
};

// band == nullptr: every column sums all rows. Also counts clipped pixels
// (0 or 255) on every 8th row, band or not, for the saturation flag. With
// rings and radial (no band, the rings' height), also the radial sums: the
// sums are then taken ring by ring, their totals the same bits. True when
// the radial sums were taken.
bool column_profile(const uint8_t* pixels, uint16_t width, uint16_t height, uint16_t stride,
                    const ColumnBand* band, ColumnProfile& out, const RadialRings* rings = nullptr,
                    RadialSums* radial = nullptr);

// Both cameras delivered the same textured image (one frame twice: a wiring
// or driver fault): every column sum equal, and not all columns alike. Two
// real cameras never give this: their independent pixel noise (and, for a
// rig that is not perfectly aligned, their different views) makes some sum
// differ, however far and weak the scene; a far scene is low texture, which
// rms(F1 - F0) measures. A flat profile is left to low texture as well.
// Flat: every column's sum in proportion to the rows it sums (band, as
// given to column_profile; nullptr: all rows).
bool same_textured_profile(const ColumnProfile& a, const ColumnProfile& b, const ColumnBand* band, uint16_t height);

// Rows column u sums, Q8: its whole rows and its two fractional ones
// (height * 256 when band == nullptr, for the plain sums' proportions).
uint32_t band_rows_q8(const ColumnBand* band, uint16_t height, uint16_t u);

}  // namespace lumavel
