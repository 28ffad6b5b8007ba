// Two cameras that clip at different scene brightness, made to clip alike.
//
// A camera with more gain (or its own auto-exposure) saturates at 255 on
// parts of the scene that the other still resolves; after the division by
// the mean brightness, the brighter camera's bright texture is flattened and
// the darker one's is not, and their difference reads as velocity (the photo
// wall with cam1 at 1.2x the gain: E 15 % against 0.9 % for twins). The
// photometric match cannot learn it: it follows the scene.
//
// Both cameras see nearly the same scene, so the ratio of their mean
// brightness is their gain ratio g (to the black levels' share). Where the
// brighter camera has pixels at 255, the darker one's pixels are clamped at
// 255 / g: both then lose the same part of the scene. Only where the brighter
// camera clips on more than kClipShareRatio times the share of pixels the
// darker one does: a gain difference makes the brighter camera clip on far
// more (cheap_pair: 1.5-5 % against 0.01 %), while twins whose means differ
// by what each camera sees (2-9 % for seconds along a photo wall 2 m away)
// clip on like shares, and clamping them moved a twin slalom's mean error
// from -0.0142 to -0.0160 m/s (with the rule: -0.0143). Applied to the
// sensor's pixels before binning (clipping happens per sensor pixel; a binned
// pixel averages clipped and unclipped ones). No state: each frame pair on
// its own. (Matching the share of clipped pixels instead, by histogram, was
// tried: near clutter, which the two cameras see differently, took it far
// off; the means are steadier.)
//
// Cost: one pass over both frames (a sum and a count) and one clamping pass
// over the darker frame when the brighter one clips.
#pragma once
#include <cstdint>

#include "lumavel/core/binning.hpp"

namespace lumavel {

struct ClipStats {
  uint64_t sum;     // of the pixels
  uint32_t pixels;  // (at most 2^24: bin_area's limit)
  uint32_t at_max;  // pixels at 255
};

void clip_stats(const ImageView& in, ClipStats& s);

// The brighter camera's share of pixels at 255 must exceed this many times the
// darker one's (2 and 4 measured alike on the mismatched renders; 4 took the
// cheap_pair photo wall from 6.99 to 7.30 %).
constexpr uint64_t kClipShareRatio = 2;

// The level each camera's pixels are clamped at: 255 (left as they are)
// except the darker camera's when the brighter one clips on more than
// kClipShareRatio times its share.
void match_clip_ceilings(const ClipStats& s0, const ClipStats& s1, uint8_t ceiling[2]);

// Clamps a frame in place (rows of `width` pixels, `stride` bytes apart).
void clamp_pixels(uint8_t* px, uint16_t width, uint16_t height, uint32_t stride, uint8_t ceiling);

}  // namespace lumavel
