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
};

// Every bit defined above (a decoder refuses the others).
constexpr uint16_t kKnownStatusFlags = 0x03FFu;


}  // namespace lumavel
