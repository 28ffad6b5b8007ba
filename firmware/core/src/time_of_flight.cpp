#include "lumavel/core/time_of_flight.hpp"

#include "lumavel/core/fusion_params.hpp"
#include "lumavel/core/imath.hpp"

namespace lumavel {
namespace {

using namespace params;

// Squared gates in Q16 (residuals are compared as squares: no root per segment).
constexpr int64_t kPathResidualSqQ16 = fx::q_of(kTofMaxPathResidual * kTofMaxPathResidual, 16);
constexpr int64_t kMotionResidualSqQ16 = fx::q_of(kTofMaxResidualVsMotion * kTofMaxResidualVsMotion, 16);
constexpr int64_t kGateFramesQ16 = fx::q_of(kTofTrackGateFrames, 16);
constexpr int64_t kGateFractionQ16 = fx::q_of(kTofTrackGateFraction, 16);
constexpr int64_t kAgreementQ16 = fx::q_of(kTofAcquireAgreement, 16);
constexpr int64_t kAcquireMinSpeedQ16 = fx::q_of(kTofAcquireMinSpeed, fx::kSpeedFrac);

int64_t abs64(int64_t v) { return v < 0 ? -v : v; }

// How far a tracked tau may move in one frame.
int64_t gate_ns(int64_t tau_ns, int64_t frame_ns) {
  const int64_t a = (kGateFramesQ16 * frame_ns) >> 16;
  const int64_t b = (kGateFractionQ16 * abs64(tau_ns)) >> 16;
  return a > b ? a : b;
}

// direction * h / tau in SpeedQ16 (h Q24 m, tau ns).
SpeedQ16 speed_of(LengthQ24 h, int8_t direction, int64_t tau_ns) {
  return fx::div_q(int64_t{direction} * h * 1000000000, tau_ns * 256, 0);
}

}  // namespace

void TimeOfFlight::reset() { *this = TimeOfFlight{}; }

void TimeOfFlight::push(const TofFrame& frame) {
  ring_[head_] = frame;
  head_ = static_cast<uint16_t>((head_ + 1) % kTofFrames);
  if (count_ < kTofFrames) ++count_;
}

const TofFrame& TimeOfFlight::at(uint16_t back) const {
  return ring_[(head_ + kTofFrames - 1 - back) % kTofFrames];
}

bool TimeOfFlight::search(const TofTrackInput& in, int trail, uint16_t first, uint16_t last, int64_t want_ns,
                          Candidate& out) const {
  const int lead = 1 - trail;
  const TofFrame& now = at(0);
  const TofFrame& before = at(1);
  // The trail camera's own change since its previous frame, Q48.
  int64_t motion = 0;
  for (uint8_t k = 0; k < in.count; ++k) {
    const int64_t d = fx::shr_round(int64_t{now.f[trail][k]} - before.f[trail][k], 4);
    motion += d * d;
  }
  bool found = false;
  for (uint16_t back = first; back <= last && back + 1 < count_; ++back) {
    const TofFrame& b = at(back);
    const TofFrame& a = at(static_cast<uint16_t>(back + 1));
    // Tracking: only segments whose time span reaches the wanted tau.
    if (want_ns > 0) {
      const int64_t lo = static_cast<int64_t>(now.t_ns - b.t_ns), hi = static_cast<int64_t>(now.t_ns - a.t_ns);
      const int64_t g = gate_ns(want_ns, static_cast<int64_t>(now.t_ns - before.t_ns));
      if (hi < want_ns - g || lo > want_ns + g) continue;
    }
    const int64_t dth = now.heading - (a.heading + b.heading) / 2;
    if (abs64(dth) > in.max_rotation) continue;
    int64_t ee = 0, ed = 0, dd = 0;  // Q48
    for (uint8_t k = 0; k < in.count; ++k) {
      // The trail's outputs rotated back to the lead's heading: F - dtheta * mean(dF/dtheta).
      const int64_t rb = (int64_t{now.r[trail][k]} + (int64_t{a.r[lead][k]} + b.r[lead][k]) / 2) / 2;  // Q20
      const int64_t tv = int64_t{now.f[trail][k]} - fx::shr_round(dth * rb, fx::kSlopeFrac);           // Q28
      const int64_t e = fx::shr_round(tv - a.f[lead][k], 4);
      const int64_t d = fx::shr_round(int64_t{b.f[lead][k]} - a.f[lead][k], 4);
      ee += e * e;
      ed += e * d;
      dd += d * d;
    }
    if (dd <= 0 || ed < 0 || ed > dd) continue;
    const int64_t fr = fx::div_q(ed, dd, 16);  // Q16 in [0, 1]
    int64_t res = ee - fx::shr_round(fr * ed, 16);
    if (res < 0) res = 0;
    if (res > (kPathResidualSqQ16 * (dd >> 16)) || res > (kMotionResidualSqQ16 * (motion >> 16))) continue;
    const int64_t span = static_cast<int64_t>(b.t_ns - a.t_ns);
    const int64_t t_lead = static_cast<int64_t>(a.t_ns) + ((span * fr) >> 16);
    const int64_t tau = static_cast<int64_t>(now.t_ns) - t_lead;
    if (tau <= 0) continue;
    const int64_t stau = trail == 0 ? tau : -tau;
    const bool better = !found || (want_ns > 0 ? abs64(tau - want_ns) < abs64(abs64(out.stau_ns) - want_ns) : res < out.res);
    if (!better) continue;
    found = true;
    out.stau_ns = stau;
    out.res = res;
    // Timing uncertainty: the residual over the segment's step, in frames, times the step.
    const uint32_t sig_q16 = fx::isqrt32(static_cast<uint32_t>(fx::div_q(res, dd, 32)));
    out.sig_ns = (span * int64_t{sig_q16}) >> 16;
    out.y_then = a.y + (((b.y - a.y) * fr) >> 16);
  }
  return found;
}

TofResult TimeOfFlight::track(const TofTrackInput& in) {
  TofResult r{};
  if (count_ < 3) {
    misses_ = 255;
    return r;
  }
  const uint16_t last = static_cast<uint16_t>(count_ - 2);
  const int64_t frame_ns = static_cast<int64_t>(at(0).t_ns - at(1).t_ns);
  Candidate pick{};
  bool have = false;
  if (misses_ < kTofTrackMisses) {
    Candidate c{};
    const int trail = track_ns_ > 0 ? 0 : 1;
    if (search(in, trail, 0, last, abs64(track_ns_), c) &&
        abs64(abs64(c.stau_ns) - abs64(track_ns_)) < gate_ns(track_ns_, frame_ns)) {
      pick = c;
      have = true;
    }
  }
  if (!have) {
    if (misses_ < 255) ++misses_;
    // (Re)acquisition: the best candidate of either direction that agrees with
    // the fused velocity, confirmed over several frames.
    Candidate best{};
    bool any = false;
    for (int trail = 0; trail < 2; ++trail) {
      Candidate c{};
      if (!search(in, trail, 0, last, 0, c)) continue;
      const SpeedQ16 v = speed_of(in.baseline, c.stau_ns > 0 ? 1 : -1, abs64(c.stau_ns));
      const int64_t vf = in.v_fused;
      if (abs64(vf) > kAcquireMinSpeedQ16 && abs64(int64_t{v} - vf) > ((kAgreementQ16 * abs64(vf)) >> 16)) continue;
      if (!any || c.res < best.res) {
        best = c;
        any = true;
      }
    }
    if (any) {
      const bool same = acquire_count_ > 0 && (best.stau_ns > 0) == (acquire_ns_ > 0) &&
                        abs64(abs64(best.stau_ns) - abs64(acquire_ns_)) < gate_ns(acquire_ns_, frame_ns);
      acquire_count_ = same ? static_cast<uint8_t>(acquire_count_ + 1) : 1;
      acquire_ns_ = best.stau_ns;
      if (acquire_count_ >= kTofAcquireFrames) {
        pick = best;
        have = true;
        acquire_count_ = 0;
      }
    } else {
      acquire_count_ = 0;
    }
  }
  if (!have) return r;
  track_ns_ = pick.stau_ns;
  misses_ = 0;
  r.ok = true;
  r.direction = pick.stau_ns > 0 ? 1 : -1;
  r.tau_ns = abs64(pick.stau_ns);
  r.v = speed_of(in.baseline, r.direction, r.tau_ns);
  r.sig = fx::div_q(pick.sig_ns, r.tau_ns, fx::kFracFrac);
  r.y_then = pick.y_then;
  return r;
}

}  // namespace lumavel
