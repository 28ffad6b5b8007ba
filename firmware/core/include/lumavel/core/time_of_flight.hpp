// The depth-free measurement: when the rig moves along its baseline, the
// trail camera passes where the lead camera was. The time it takes,
// tau = h / V on average, does not depend on the scene's depth at all.
//
// A short history keeps both cameras' kernel outputs F and dF/dtheta frame by
// frame. Every frame, the trail camera's current outputs (rotated back to the
// lead's heading of the moment, to first order, with the gyro) are looked for
// on the lead camera's path through kernel space: on each segment between two
// of its frames, the closest point (linear interpolation in time) and its
// residual distance. A segment counts when the residual is small against the
// segment's step and against the trail camera's own frame-to-frame change,
// and when the rotation between the two sightings is small. cam0 trailing
// means the body moved +h (along body x) since then; cam1 trailing, -h.
//
// Of all the candidates, the tracker keeps the one that continues the tracked
// time of flight (it moves smoothly from frame to frame); without a track it
// takes a new one only after the same candidate held for several frames and
// agrees with the fused velocity (periodic scenes offer wrong matches too).
// A track lost for kTofLostTime while no candidate agrees with the hints is
// also looked for unguided, and taken after kTofLostAcquireFrames.
// Reversals, standstill and speeds too slow for the history simply leave no
// candidate: the caller falls back to the differential observer alone.
//
// Cost: a track is searched on the segments near the tracked tau; without one,
// on the taus that agree with the fused velocity in its direction, or below
// kTofAcquireMinSpeed on every usable tau of both directions.
#pragma once
#include <cstdint>

#include "lumavel/core/fixed.hpp"
#include "lumavel/core/fusion_params.hpp"
#include "lumavel/core/limits.hpp"

namespace lumavel {

// The longest time of flight that is searched for and used, ns.
constexpr int64_t kTofMaxTauNs = fx::q_of(params::kTofMaxTau * 1e9, 0);

// One usable frame: both cameras' kernel outputs and what the fusion needs.
struct TofFrame {
  uint64_t t_ns;
  int64_t heading;                     // offset-corrected gyro integral, unwrapped, Q28 rad
  ValueQ28 f[2][kMaxKernels];          // F per camera
  SlopeQ20 r[2][kMaxKernels];          // dF/dtheta per camera
  TravelQ16Ns y;                       // integral of the differential's direct values (raw, unscaled)
};

struct TofResult {
  bool ok;
  bool held;          // no match this frame, but the track is kept (fewer than kTofTrackMisses misses)
  int8_t direction;   // +1: cam0 trails, the body moved +h since the match; -1: cam1 trails, -h
  int64_t tau_ns;     // time since the lead camera stood here
  SpeedQ16 v;         // displacement over tau: direction * h / tau
  FracQ16 sig;        // relative uncertainty of v (the match's timing uncertainty over tau)
  TravelQ16Ns y_then; // TofFrame::y at the match (the differential's travel over the window: travel_between)
  AngleQ28 turn;      // the gyro's rotation over the window, frame by frame in absolute value (>= 0)
  uint8_t frames;     // frames the track has held since it was taken (saturating)
};

struct TofTrackInput {
  LengthQ24 baseline;          // h (signed: x of cam1 minus x of cam0)
  AngleQ28 max_rotation;       // rotation allowed between the sightings
  SpeedQ16 v_fused;            // the current fused velocity (a new track must agree with it ...
  SpeedQ16 v_direct;           // ... or with this frame's direct value, scaled; v_fused without one)
  uint8_t count;               // kernels
  int8_t direction;            // the images' direction of travel (image_direction.hpp), 0 unknown: no
                               // track against it is taken or kept
};

class TimeOfFlight {
 public:
  void reset();
  // The slot of the newest frame, to be filled before track() (no copy).
  TofFrame& push();
  // The time of flight of the newest frame (push it first).
  TofResult track(const TofTrackInput& in);
  uint16_t frames() const { return count_; }

 private:
  struct Candidate {
    int64_t stau_ns;   // signed: + cam0 trails, - cam1 trails
    int64_t res;       // residual, Q48
    int64_t sig_ns;    // timing uncertainty
    TravelQ16Ns y_then;
    AngleQ28 turn;     // the gyro's rotation over the window, frame by frame in absolute value
  };
  const TofFrame& at(uint16_t back) const;  // 0 = newest
  // The best candidate of one direction on the segments whose time span
  // reaches [min_ns, max_ns]: the one nearest want_ns (> 0: tracking), else
  // the one with the least residual. Tracking a track that has held
  // kTofWindowGateFrames, the window's gate may widen the step's (kTofMaxTauShift).
  bool search(const TofTrackInput& in, int trail, int64_t want_ns, int64_t min_ns, int64_t max_ns, Candidate& out) const;
  // The time, as a fraction of segment back's span (Q16), of the point at fr
  // along its chord d (Q24 per kernel, |d|^2 = dd, Q48): kTofChordMaxShift.
  int64_t chord_time(int lead, uint16_t back, uint8_t count, const int32_t* d, int64_t dd, int64_t fr) const;
  // On the newest segment, where tau is under a frame: the fraction (Q16) at
  // which the stereo cubic meets the trail's F now, searched over the
  // segment, and its squared residual (Q48, the chord's units). False where
  // the cubic does not apply (no frame before the segment, or one not a
  // frame before it: a dropped frame) or its point lies further than
  // kTofCubicMaxMove from the chord's fr.
  bool stereo_cubic(int trail, uint8_t count, int64_t fr, int64_t* s_out, int64_t* res_out) const;

  TofFrame ring_[kTofFrames];
  uint16_t head_ = 0;   // next slot to write
  uint16_t count_ = 0;
  int64_t track_ns_ = 0;        // tracked signed tau
  uint8_t misses_ = 255;
  uint8_t track_frames_ = 0;    // frames the track has held since it was acquired (saturating)
  uint8_t acquire_count_ = 0;
  uint8_t acquire_gap_ = 0;     // frames in a row without a candidate since the run's last
  int64_t acquire_ns_ = 0;
  uint64_t track_t_ns_ = 0;     // the newest frame's time when a track last held (read only once held_once_)
  bool held_once_ = false;       // a track has held since the history began
};

}  // namespace lumavel
