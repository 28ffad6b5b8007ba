// Status flags raised by the estimator, one bit each, stable across releases
// (they travel in the HID report and the estimates CSV).
#pragma once
#include <cstdint>

namespace lumavel {

enum StatusFlag : uint16_t {
  kStatusConverging = 1u << 0,  // observer (re)started less than 3 time constants ago
  kStatusLowTexture = 1u << 1,  // dF/dx too weak to observe V: V is held
  kStatusSaturated = 1u << 2,   // clipped pixels, a saturated fixed-point step or a railed gyro sample
  kStatusFrameGap = 1u << 3,    // frame interval longer than 1.5 nominal periods
  kStatusGyroGap = 1u << 4,     // gyro samples do not cover the frame interval (GyroIntegrator::covers)
  kStatusNoLight = 1u << 5,     // normaliser (mean brightness) is zero: frame unusable
  kStatusRestarted = 1u << 6,   // gap too long to bridge: the observer restarted here
  kStatusStill = 1u << 7,       // images static: the gyro's zero-rate offset is being learned
  kStatusNoStereo = 1u << 8,    // both cameras delivered the same image: no stereo difference,
                                // V not observable, frame unusable (with kStatusLowTexture: V held)
  kStatusNoTof = 1u << 9,       // no time-of-flight match this frame (standstill, too slow for the
                                // history, turning, reversing, or lost): V from the differential alone
  kStatusAgainstImages = 1u << 10,  // V runs against the images' own direction of travel
                                    // (image_direction.hpp): a texture that repeats within about
                                    // 2h aliases the stereo difference; V is not to be trusted
};

// Every bit defined above (a decoder refuses the others).
constexpr uint16_t kKnownStatusFlags = 0x07FFu;

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
    {kStatusNoStereo, "NO_STEREO", "both cameras the same image, V held"},
    {kStatusNoTof, "NO_TOF", "no time of flight, differential alone"},
    {kStatusAgainstImages, "AGAINST_IMAGES", "V against the images' direction of travel"},
};

}  // namespace lumavel
