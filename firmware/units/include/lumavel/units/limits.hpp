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

#ifndef LUMAVEL_MATCH_FRAMES
#define LUMAVEL_MATCH_FRAMES 16  // frames of history for the photometric match (photometric_match.hpp); 0: not built in
#endif

namespace lumavel {
constexpr int kMinColumns = 16;
constexpr int kMaxColumns = LUMAVEL_MAX_COLS;
constexpr int kMaxRows = LUMAVEL_MAX_ROWS;
constexpr int kMaxKernels = LUMAVEL_MAX_KERNELS;
constexpr int kMaxKernelOrder = 3;
constexpr int kTofFrames = LUMAVEL_TOF_FRAMES;
static_assert(kTofFrames >= 4, "the time of flight needs a few frames of history");
constexpr int kMatchFrames = LUMAVEL_MATCH_FRAMES;
static_assert(kMatchFrames == 0 || kMatchFrames >= 2, "the photometric match interpolates between frames");
static_assert(kMatchFrames == 0 || kMaxRows > 1,
              "the photometric match maps to Q8 (32-bit) column sums: a line-scan build sets LUMAVEL_MATCH_FRAMES=0");
constexpr bool kHavePhotometricMatch = kMatchFrames > 0;
// The default working resolution: 40x30 (plenty for the method, cheap on a
// microcontroller), or the sensor's own size on an axis where it is smaller
// (a 20x15 sensor works at 20x15, a line scan at height 1). The one rule for
// the host tools and the device defaults.
constexpr int kDefaultColumns = 40;
constexpr int kDefaultRows = 30;
constexpr int default_columns(int sensor_columns) {
  return sensor_columns < kDefaultColumns ? sensor_columns : kDefaultColumns;
}
constexpr int default_rows(int sensor_rows) { return sensor_rows < kDefaultRows ? sensor_rows : kDefaultRows; }
static_assert(kMaxRows <= 128, "column sums must fit 15 bits");
static_assert(kMaxColumns >= kMinColumns, "at least 16 columns");
}  // namespace lumavel
