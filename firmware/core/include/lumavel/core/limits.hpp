// Compile-time capacities. Boards with little RAM lower them with
// -DLUMAVEL_MAX_COLS=... etc.; all memory of the core is sized from these.
#pragma once

#ifndef LUMAVEL_MAX_COLS
#define LUMAVEL_MAX_COLS 160
#endif
#ifndef LUMAVEL_MAX_ROWS
#define LUMAVEL_MAX_ROWS 128  // column sums stay below 2^15 (255 * 128)
#endif
#ifndef LUMAVEL_MAX_KERNELS
#define LUMAVEL_MAX_KERNELS 6
#endif
#ifndef LUMAVEL_TOF_FRAMES
#define LUMAVEL_TOF_FRAMES 64  // frames of history for the time of flight (time_of_flight.hpp)
#endif

namespace lumavel {
constexpr int kMinColumns = 16;
constexpr int kMaxColumns = LUMAVEL_MAX_COLS;
constexpr int kMaxRows = LUMAVEL_MAX_ROWS;
constexpr int kMaxKernels = LUMAVEL_MAX_KERNELS;
constexpr int kMaxKernelOrder = 3;
constexpr int kTofFrames = LUMAVEL_TOF_FRAMES;
static_assert(kTofFrames >= 4, "the time of flight needs a few frames of history");
static_assert(kMaxRows <= 128, "column sums must fit 15 bits");
static_assert(kMaxColumns >= kMinColumns, "at least 16 columns");
}  // namespace lumavel
