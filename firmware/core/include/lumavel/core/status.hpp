// Status flags raised by the estimator, one bit each, stable across releases
// (they travel in the HID report and the estimates CSV).
#pragma once
#include <cstdint>

namespace lumavel {

enum StatusFlag : uint16_t {
  kStatusConverging = 1u << 0,  // observer (re)started less than 3 time constants ago
  kStatusLowTexture = 1u << 1,  // dF/dx too weak to observe V: V is held
  kStatusSaturated = 1u << 2,   // clipped pixels or a saturated fixed-point step
  kStatusFrameGap = 1u << 3,    // frame interval longer than 1.5 nominal periods
  kStatusGyroGap = 1u << 4,     // gyro samples missing over the frame interval
  kStatusNoLight = 1u << 5,     // normaliser (mean brightness) is zero: frame unusable
  kStatusRestarted = 1u << 6,   // gap too long to bridge: the observer restarted here
  kStatusStill = 1u << 7,       // images static: the gyro's zero-rate offset is being learned
};

// Every flag with its name (as lumavel-read prints it) and what it means in
// words, in bit order: the one table for summaries, plots and readers.
struct StatusFlagInfo {
  StatusFlag flag;
  const char* name;
  const char* meaning;
};
inline constexpr StatusFlagInfo kStatusFlags[] = {
    {kStatusConverging, "CONVERGING", "converging"},
    {kStatusLowTexture, "LOW_TEXTURE", "low texture, V held"},
    {kStatusSaturated, "SATURATED", "saturated pixels or arithmetic"},
    {kStatusFrameGap, "FRAME_GAP", "frame gap"},
    {kStatusGyroGap, "GYRO_GAP", "gyro gap"},
    {kStatusNoLight, "NO_LIGHT", "no light, V held"},
    {kStatusRestarted, "RESTARTED", "observer restarted"},
    {kStatusStill, "STILL", "still, gyro offset learned"},
};

}  // namespace lumavel
