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

// Bit 0 of each byte of the result set where that byte of w is not clipped
// (0x00 or 0xFF), without branches: a byte is clipped iff its 8 bits are
// equal, i.e. iff (b ^ b >> 1) & 0x7F == 0. Added word by word into byte
// lanes and summed once a row (a sum per word, a multiply and two shifts
// more, took 16 instructions a word with the loop on M3).
uint32_t unclipped_lanes(uint32_t w) {
  const uint32_t y = (w ^ (w >> 1)) & 0x7F7F7F7Fu;
  return (((y + 0x7F7F7F7Fu) | y) & 0x80808080u) >> 7;  // bit 7: byte of y != 0
}
// A lane counts one per word of a row: at most kMaxColumns / 4.
static_assert(kMaxColumns / 4 <= 255, "a row's unclipped count must fit a byte lane");
uint32_t lanes_sum(uint32_t lanes) {
  const uint32_t pairs = (lanes & 0x00FF00FFu) + ((lanes >> 8) & 0x00FF00FFu);
  return (pairs & 0xFFFFu) + (pairs >> 16);
}

// Sums of rows [from, to) of the 4 * Words columns at p: two 16-bit lanes per
// register (255 * 128 < 2^16), so each pixel costs about one load share and
// one add; Words words a row share the loop's pointer step, compare and
// branch (four words: 19 instructions per 16 pixels on M3).
// Word-aligned rows take the aligned path (one LDR per four pixels).
// Inlined: a call per group of columns costs more than the band's own work.
// Rows [from, to) and [from2, to2) (a radial ring's two halves; from2 ==
// to2 for one range). A Ring adds them to out and, times the ring's weight
// c, to s2 (first: stores them instead), where the lanes are unpacked.
struct Ring {
  int32_t* s2;
  int32_t c;
  bool first;
};
template <unsigned Words, bool Radial = false>
__attribute__((always_inline)) inline void column_sums(const uint8_t* p, uint16_t from, uint16_t to, uint16_t from2,
                                                        uint16_t to2, uint16_t stride, bool aligned, ColumnSum* out,
                                                        Ring ring = {}) {
  // Without SIMD, the even bytes are not masked at all: the words' plain sum
  // (wrapping) is even + (odd << 8) exactly, and even < 2^32, so even is that
  // sum less odd << 8, mod 2^32 (four operations a word where five were).
  uint32_t even[Words] = {}, odd[Words] = {};
  // The odd bytes' mask, opaque to the compiler on Thumb-2 without SIMD (an
  // empty asm: no instruction): held in a register, it ANDs w shifted in one
  // instruction, where the immediate form takes a shift and an AND (M3 at
  // 160x120: 139 023 -> 129 588 instructions a frame).
  uint32_t mask = 0x00FF00FFu;
#if defined(__thumb2__) && !defined(__ARM_FEATURE_SIMD32)
  __asm__("" : "+r"(mask));
#endif
  for (int range = 0; range < 2; ++range) {
    const uint8_t* q = p + uint32_t{range == 0 ? from : from2} * stride;
    const uint8_t* const end = p + uint32_t{range == 0 ? to : to2} * stride;
    if (aligned) {
      for (; q < end; q += stride) {
        const uint8_t* const row = static_cast<const uint8_t*>(__builtin_assume_aligned(q, 4));
        for (unsigned k = 0; k < Words; ++k) {
          const uint32_t w = load_word(row + 4 * k);
#if defined(__ARM_FEATURE_SIMD32)
          // Cortex-M4/M7: UXTAB16 adds bytes 0 and 2 (or 1 and 3, rotated) to two 16-bit lanes.
          even[k] = __uxtab16(even[k], w);
          odd[k] = __uxtab16(odd[k], (w >> 8) | (w << 24));  // UXTAB16 with ROR #8
#else
          even[k] += w;
          odd[k] += (w >> 8) & mask;
#endif
        }
      }
    } else {
      for (; q < end; q += stride)
        for (unsigned k = 0; k < Words; ++k) {
          const uint32_t w = load_word(q + 4 * k);
#if defined(__ARM_FEATURE_SIMD32)
          even[k] += w & 0x00FF00FFu;
#else
          even[k] += w;
#endif
          odd[k] += (w >> 8) & mask;
        }
    }
  }
#if !defined(__ARM_FEATURE_SIMD32)
  for (unsigned k = 0; k < Words; ++k) even[k] -= odd[k] << 8;
#endif
  uint8_t probe[4] = {1, 0, 0, 0};
  const bool little = load_word(probe) == 1u;
  for (unsigned k = 0; k < Words; ++k) {
    const auto lo_e = static_cast<ColumnSum>(even[k] & 0xFFFFu), hi_e = static_cast<ColumnSum>(even[k] >> 16);
    const auto lo_o = static_cast<ColumnSum>(odd[k] & 0xFFFFu), hi_o = static_cast<ColumnSum>(odd[k] >> 16);
    ColumnSum* const o = out + 4 * k;
    const ColumnSum lanes[4] = {little ? lo_e : hi_o, little ? lo_o : hi_e, little ? hi_e : lo_o, little ? hi_o : lo_e};
    for (unsigned i = 0; i < 4; ++i) {
      if (Radial) {
        o[i] = static_cast<ColumnSum>(ring.first ? lanes[i] : o[i] + lanes[i]);
        int32_t* const s2 = ring.s2 + 4 * k + i;
        *s2 = (ring.first ? 0 : *s2) + ring.c * int32_t{lanes[i]};
      } else {
        o[i] = lanes[i];
      }
    }
  }
}

// Two and four words a row where the registers hold their lanes: not on
// ARMv6-M (eight low registers) or RV32E (sixteen), where the spills cost
// more than the loop's step (M0+ 11 222 -> 11 963 instructions at 40x30),
// nor on a line scan (one row: nothing to share, only flash to spend).
#if defined(__ARM_ARCH_6M__) || defined(__riscv_32e) || defined(__riscv_e)
constexpr bool kWideColumnSums = false;
#else
constexpr bool kWideColumnSums = kMaxRows > 1;
#endif

// Every column's sum of rows [from, to) and [from2, to2), no band; with
// Radial, added to out and to ring.s2 as column_sums does.
template <bool Radial>
void sum_rows(const uint8_t* pixels, uint16_t width, uint16_t from, uint16_t to, uint16_t from2, uint16_t to2,
              uint16_t stride, bool aligned, ColumnSum* out, Ring ring = {}) {
  uint16_t u = 0;
  const auto at = [&](uint16_t c) { return Ring{ring.s2 + c, ring.c, ring.first}; };
  if (kWideColumnSums) {
    for (; u + 16 <= width; u += 16)
      column_sums<4, Radial>(pixels + u, from, to, from2, to2, stride, aligned, &out[u], Radial ? at(u) : ring);
    for (; u + 8 <= width; u += 8)
      column_sums<2, Radial>(pixels + u, from, to, from2, to2, stride, aligned, &out[u], Radial ? at(u) : ring);
  }
  for (; u + 4 <= width; u += 4)
    column_sums<1, Radial>(pixels + u, from, to, from2, to2, stride, aligned, &out[u], Radial ? at(u) : ring);
  for (; u < width; ++u) {
    int32_t s = 0;
    for (uint16_t r = from; r < to; ++r) s += pixels[u + uint32_t{r} * stride];
    for (uint16_t r = from2; r < to2; ++r) s += pixels[u + uint32_t{r} * stride];
    if (Radial) {
      out[u] = static_cast<ColumnSum>(ring.first ? s : out[u] + s);
      ring.s2[u] = (ring.first ? 0 : ring.s2[u]) + ring.c * s;
    } else {
      out[u] = static_cast<ColumnSum>(s);
    }
  }
}

// Ring k's rows (column_profile.hpp): [from, to) and their mirrors [from2,
// to2); the middle ring one range (from2 == to2).
struct RingRows {
  uint16_t from, to, from2, to2;
};
RingRows ring_rows(const RadialRings& r, int k) {
  const uint16_t outer = k == 0 ? 0 : r.edge[k - 1];
  if (k == kRadialRings - 1) return {outer, static_cast<uint16_t>(r.height - outer), 0, 0};
  return {outer, r.edge[k], static_cast<uint16_t>(r.height - r.edge[k]), static_cast<uint16_t>(r.height - outer)};
}

// The sums ring by ring, each ring's also into sum_y2 at its weight: the
// totals are sum_rows()'s over all rows, bit for bit.
void sum_rows_radial(const uint8_t* pixels, uint16_t width, uint16_t stride, bool aligned, const RadialRings& rings,
                     ColumnProfile& out, RadialSums& radial) {
  for (int k = 0; k < kRadialRings; ++k) {
    const RingRows rr = ring_rows(rings, k);
    sum_rows<true>(pixels, width, rr.from, rr.to, rr.from2, rr.to2, stride, aligned, out.sum,
                   Ring{radial.sum_y2, rings.weight_q8[k], k == 0});
  }
}

// Column c's sum of rows [from, height - from) narrowed to its band, in Q8.
int32_t to_band_q8(const uint8_t* col, int32_t s, uint16_t from, uint16_t height, uint16_t stride,
                    uint16_t first, uint8_t edge_q8) {
  for (uint16_t r = from; r < first; ++r) s -= col[uint32_t{r} * stride] + col[uint32_t(height - 1 - r) * stride];
  s <<= 8;
  if (first > 0) s += int32_t{edge_q8} * (col[uint32_t(first - 1) * stride] + col[uint32_t(height - first) * stride]);
  return s;
}

bool little_endian() {
  uint8_t probe[4] = {1, 0, 0, 0};
  return load_word(probe) == 1u;
}

// The edge rows' 3 (t + b) - t' - b' (column_profile below) four columns a
// step on word-aligned rows: the even and the odd bytes in two 16-bit lanes
// each, 512 above the value, so that every lane stays in [2, 2042] at each
// step (no borrow or carry between lanes); then h edge - 4 sum per column,
// the same integers as the byte loop (M3: 15 instructions a column there).
// Returns the columns done (n rounded down to a multiple of 4). Where
// kWideColumnSums (on ARMv6-M its spills made the 160x120 frame some 2 900
// instructions longer).
uint32_t edge_words(const uint8_t* top, const uint8_t* bottom, uint16_t stride, uint32_t n, int32_t h,
                    ColumnProfile& out) {
  constexpr uint32_t kMask = 0x00FF00FFu, kBias = 0x02000200u;
  const int32_t bias = 512 * h;  // h (lane - 512) = h lane - 512 h
  uint32_t c = 0;
  for (; c + 4 <= n; c += 4) {
    const auto word = [&](const uint8_t* row) {
      return load_word(static_cast<const uint8_t*>(__builtin_assume_aligned(row + c, 4)));
    };
    const uint32_t t = word(top), b = word(bottom), t2 = word(top + stride), b2 = word(bottom - stride);
    const uint32_t even = 3 * ((t & kMask) + (b & kMask)) + kBias - (t2 & kMask) - (b2 & kMask);
    const uint32_t odd =
        3 * (((t >> 8) & kMask) + ((b >> 8) & kMask)) + kBias - ((t2 >> 8) & kMask) - ((b2 >> 8) & kMask);
    const int32_t lanes[4] = {static_cast<int32_t>(even & 0xFFFFu), static_cast<int32_t>(odd & 0xFFFFu),
                              static_cast<int32_t>(even >> 16), static_cast<int32_t>(odd >> 16)};
    for (uint32_t i = 0; i < 4; ++i) out.edge4[c + i] = h * lanes[i] - bias - 4 * int32_t{out.sum[c + i]};
  }
  return c;
}

}  // namespace

bool column_profile(const uint8_t* pixels, uint16_t width, uint16_t height, uint16_t stride,
                    const ColumnBand* band_in, ColumnProfile& out, const RadialRings* rings, RadialSums* radial) {
  // A line-scan build keeps no band (kBandColumns == 1).
  const ColumnBand* const band = kBandColumns > 1 ? band_in : nullptr;
  out.width = width;
  out.q8 = band != nullptr;
  out.plain_x256 = false;
  const bool aligned = ((reinterpret_cast<uintptr_t>(pixels) | stride) & 3u) == 0;
  const bool radial_taken = rings != nullptr && radial != nullptr && band == nullptr && kBandColumns > 1 &&
                            height >= 2 && rings->height == height;
  if (radial_taken) {
    radial->rows_y2_q8 = rings->rows_y2_q8;
    sum_rows_radial(pixels, width, stride, aligned, *rings, out, *radial);
  } else if (band == nullptr) {
    sum_rows<false>(pixels, width, 0, height, 0, 0, stride, aligned, out.sum);
  } else {
    uint16_t u = 0;
    for (; u + 4 <= width; u += 4) {
      // The rows all four columns need, then each narrowed to its own band.
      uint16_t from = band->first[u];
      for (int c = 1; c < 4; ++c) from = band->first[u + c] < from ? band->first[u + c] : from;
      column_sums<1>(pixels + u, from, static_cast<uint16_t>(height - from), 0, 0, stride, aligned, &out.sum[u]);
      for (int c = 0; c < 4; ++c)
        out.sum[u + c] = static_cast<ColumnSum>(to_band_q8(pixels + u + c, out.sum[u + c], from, height, stride, band->first[u + c],
                                    band->edge_q8[u + c]));
    }
    for (; u < width; ++u) {
      const uint16_t first = band->first[u];
      int32_t s = 0;
      const uint8_t* p = pixels + u;
      for (uint16_t r = first; r < height - first; ++r) s += p[uint32_t{r} * stride];
      out.sum[u] = static_cast<ColumnSum>(to_band_q8(p, s, first, height, stride, first, band->edge_q8[u]));
    }
  }
  // Edge rows (a line scan has none: its arrays are one entry long).
  out.edges = band == nullptr && kBandColumns > 1 && height >= 2;
  if (out.edges) {
    const uint8_t* top = pixels;
    const uint8_t* bottom = pixels + uint32_t(height - 1) * stride;
    const int32_t h = height;
    const uint32_t n = width < kBandColumns ? width : uint32_t{kBandColumns};
    uint32_t c = 0;
    if (kWideColumnSums && aligned && height >= 4 && little_endian()) c = edge_words(top, bottom, stride, n, h, out);
    const uint8_t* const above_bottom = bottom - stride;  // (c - stride would wrap: c is unsigned)
    for (; c < n; ++c) {
      const int32_t edge = height >= 4 ? 3 * (top[c] + bottom[c]) - top[c + stride] - above_bottom[c]
                                       : 2 * (top[c] + bottom[c]);
      out.edge4[c] = h * edge - 4 * int32_t{out.sum[c]};
    }
  }
  uint32_t clipped = 0;
  for (uint16_t r = 0; r < height; r = static_cast<uint16_t>(r + kClipRowStep)) {
    const uint8_t* p = pixels + uint32_t{r} * stride;
    const uint32_t whole = width & ~3u;  // the columns in whole words
    uint32_t lanes = 0;
    if (aligned) {
      for (const uint8_t* q = p; q < p + whole; q += 4)
        lanes += unclipped_lanes(load_word(static_cast<const uint8_t*>(__builtin_assume_aligned(q, 4))));
    } else {
      for (const uint8_t* q = p; q < p + whole; q += 4) lanes += unclipped_lanes(load_word(q));
    }
    clipped += whole - lanes_sum(lanes);
    for (uint32_t c = whole; c < width; ++c) clipped += static_cast<uint32_t>(static_cast<uint8_t>(p[c] + 1u) <= 1u);
  }
  out.clipped = clipped;
  out.clip_sampled = static_cast<uint32_t>((height + kClipRowStep - 1) / kClipRowStep) * width;
  return radial_taken;
}

RadialRings radial_rings(uint16_t width, uint16_t height) {
  RadialRings r{};
  r.height = height;
  for (int k = 0; k + 1 < kRadialRings; ++k)
    r.edge[k] = static_cast<uint16_t>((uint32_t{height} * static_cast<uint32_t>(k + 1) + kRadialRings) / (2 * kRadialRings));
  for (int k = 0; k < kRadialRings; ++k) {
    // 256 sum (2r + 1 - H)^2 / (n W^2) over the ring's rows, rounded (< 2^37).
    const RingRows rr = ring_rows(r, k);
    uint64_t num = 0;
    uint32_t n = 0;
    const auto add = [&](uint16_t from, uint16_t to) {
      for (uint16_t row = from; row < to; ++row, ++n) {
        const int32_t d = 2 * row + 1 - height;
        num += static_cast<uint64_t>(d * d);
      }
    };
    add(rr.from, rr.to);
    add(rr.from2, rr.to2);
    const uint64_t den = uint64_t{n} * width * width;
    r.weight_q8[k] = den == 0 ? 0 : static_cast<int32_t>((num * 256 + den / 2) / den);
    r.rows_y2_q8 += r.weight_q8[k] * static_cast<int32_t>(n);
  }
  return r;
}

uint32_t band_rows_q8(const ColumnBand* band, uint16_t height, uint16_t u) {
  if (band == nullptr || kBandColumns == 1) return uint32_t{height} * 256;
  const uint32_t first = band->first[u];
  return (uint32_t{height} - 2 * first) * 256 + (first > 0 ? 2 * uint32_t{band->edge_q8[u]} : 0);
}

bool same_textured_profile(const ColumnProfile& a, const ColumnProfile& b, const ColumnBand* band, uint16_t height) {
  if (a.width != b.width || a.width == 0) return false;
  bool flat = true;
  const int64_t rows0 = band_rows_q8(band, height, 0);
  for (uint16_t u = 0; u < a.width; ++u) {
    if (a.sum[u] != b.sum[u]) return false;
    // sum < 2^23, rows < 2^16 in Q8: products < 2^39.
    flat = flat && a.sum[u] * rows0 == int64_t{a.sum[0]} * band_rows_q8(band, height, u);
  }
  return !flat;
}

}  // namespace lumavel
