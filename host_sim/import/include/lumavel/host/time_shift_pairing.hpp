// A second camera synthesised from one camera on a slider: the frame cam1
// "takes" at cam0's time t is the image cam0 took when the slider was h
// further on (valid for a pure translation past a static scene). Frames only
// exist every ~1.2 cm of travel, so the image at exactly x(t) + h is made by a
// pixelwise linear blend of the two frames whose positions bracket it,
// weighted by position.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "lumavel/host/slider_dataset.hpp"

namespace lumavel::host {

// Linear interpolation of the ground-truth x at time t; NaN outside the
// ground truth's time span.
double slider_position_at(const std::vector<SliderPose>& poses, double t);

struct ShiftedPair {
  size_t cam0 = 0;    // index of cam0's frame
  size_t before = 0;  // cam1 = (1 - w) * frame[before] + w * frame[before + 1]
  double w = 0;       // in (0, 1]
};

// For each frame i (position x[i], NaN = unknown, skipped), the first later
// bracket j, j+1 with x[j] < x[i] + h <= x[j+1] (searched from i onwards, so a
// rebound at the end stop is not used). Frames with no such bracket (the end
// of the travel) get no pair. h > 0.
std::vector<ShiftedPair> plan_time_shift_pairs(const std::vector<double>& x, double h);

// out = round((1 - w) * a + w * b), n pixels.
void blend_gray(const uint8_t* a, const uint8_t* b, double w, size_t n, uint8_t* out);

}  // namespace lumavel::host
