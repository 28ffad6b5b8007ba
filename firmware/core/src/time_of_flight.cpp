#include "lumavel/core/time_of_flight.hpp"

#include <algorithm>

#include "lumavel/core/fusion_params.hpp"
#include "lumavel/core/imath.hpp"
#include "lumavel/core/kernel_dot.hpp"

namespace lumavel {
namespace {

using namespace params;

// A segment's end takes points past it by dd / kVertexSlackDiv (kTofVertexSlack).
constexpr int64_t kVertexSlackDiv = fx::q_of(1 / kTofVertexSlack, 0);
// Squared gates in Q16 (residuals are compared as squares: no root per segment).
constexpr int64_t kPathResidualSqQ16 = fx::q_of(kTofMaxPathResidual * kTofMaxPathResidual, 16);
constexpr int64_t kTauShiftQ16 = fx::q_of(kTofMaxTauShift, 16);
constexpr int64_t kPathResidualLongQ16 = fx::q_of(kTofMaxPathResidualLong, 16);
static_assert(kPathResidualLongQ16 <= (int64_t{1} << 18), "the window's gate squared stays below 2^20 (Q16)");
constexpr int64_t kMotionResidualSqQ16 = fx::q_of(kTofMaxResidualVsMotion * kTofMaxResidualVsMotion, 16);
constexpr int64_t kGateFramesQ16 = fx::q_of(kTofTrackGateFrames, 16);
constexpr int64_t kGateFractionQ16 = fx::q_of(kTofTrackGateFraction, 16);
constexpr int64_t kAgreementQ16 = fx::q_of(kTofAcquireAgreement, 16);
constexpr int64_t kAcquireMinSpeedQ16 = fx::q_of(kTofAcquireMinSpeed, fx::kSpeedFrac);
constexpr int64_t kLostNs = fx::q_of(kTofLostTime * 1e9, 0);
constexpr int64_t kOneQ16 = int64_t{1} << 16;
constexpr int64_t kChordMaxShiftQ16 = fx::q_of(kTofChordMaxShift, 16);

int64_t abs64(int64_t v) { return v < 0 ? -v : v; }
constexpr int64_t kCubicTakeQ16 = fx::q_of(kTofCubicTake, 16);
constexpr int64_t kCubicBlendQ16 = fx::q_of(kTofCubicBlend, 16);
constexpr int64_t kCubicMaxMoveQ16 = fx::q_of(kTofCubicMaxMove, 16);
constexpr int64_t kCubicEndsQ16 = fx::q_of(kTofCubicEnds, 16);
constexpr int64_t kCubicSigmaQ16 = fx::q_of(kTofCubicSigma, 16);
static_assert(kCubicBlendQ16 > kCubicTakeQ16, "the blend needs a width");
// The cubic's search: a grid over the segment that does not move with the
// chord's point (so that the twins' last bits of it cannot move the grid),
// then parabolas through three points about the best, each kTofCubicShrink
// times narrower: continuous in the costs, where halving an interval would
// turn the twins' last bits into a step of it (tau under a frame moves by
// ds / (1 - s) of itself): kTofCubicGrid, kTofCubicParabolas, kTofCubicShrink.
// The cubic's inputs held to +-4 (Q24): its coefficients then stay below 2^34 (Q24).
constexpr int64_t kCubicInMaxQ24 = int64_t{4} << 24;
constexpr int64_t kDiffMaxQ24 = int64_t{1} << 28;  // two ValueQ28 differ by < 2^32, 2^28 in Q24
static_assert(kMaxKernels <= 64, "the match's sums of squares (< 2^56 each) must stay below 2^62");

// The window's gate (kTofMaxTauShift): res <= (c tau / span)^2 dd, the gate in
// steps held to kTofMaxPathResidualLong. res and dd are Q48 sums of squares
// (< 2^62); both are brought below 2^42 by one shift, so that the gate
// squared (< 2^20, Q16) times dd fits 64 bits.
bool within_window_gate(int64_t res, int64_t dd, int64_t tau_ns, int64_t span_ns) {
  int64_t g = (kTauShiftQ16 * tau_ns) / span_ns;  // Q16 (tau <= kTofMaxTauNs < 2^30)
  if (g > kPathResidualLongQ16) g = kPathResidualLongQ16;
  const int64_t g2 = (g * g) >> 16;  // Q16
  const int s = std::max(0, kdot::bit_length(static_cast<uint64_t>(dd)) - 42);
  return (res >> s) <= ((g2 * (dd >> s)) >> 16);
}

// How far a tracked tau may move in one frame.
int64_t gate_ns(int64_t tau_ns, int64_t frame_ns) {
  const int64_t a = (kGateFramesQ16 * frame_ns) >> 16;
  const int64_t b = (kGateFractionQ16 * abs64(tau_ns)) >> 16;
  return a > b ? a : b;
}

// A candidate (signed tau: + cam0 trails) whose travel runs against the
// images' direction (ImageDirection; 0: unknown, nothing is).
bool against_images(int8_t direction, int64_t stau_ns, LengthQ24 h) {
  return direction != 0 && ((stau_ns > 0) == (h > 0)) != (direction > 0);
}

// A hint that runs against the images' direction of travel (direction: the
// sign of V that the images state, 0 none).
bool hint_against_images(int8_t direction, int64_t v_hint) { return direction != 0 && (v_hint > 0) != (direction > 0); }

// A hint fast enough to guide the acquisition, in the direction in which
// this camera trails: cam0 trails when the body moves along +h (h = x1 - x0:
// +x when cam1 is ahead, -x when cam0 is).
bool guiding(int64_t v_hint, int trail, LengthQ24 h) {
  return abs64(v_hint) > kAcquireMinSpeedQ16 && (trail == 0) == ((v_hint > 0) == (h > 0));
}

// direction * h / tau in SpeedQ16 (h Q24 m, tau ns).
SpeedQ16 speed_of(LengthQ24 h, int8_t direction, int64_t tau_ns) {
  return fx::div_q(int64_t{direction} * h * 1000000000, tau_ns * 256, 0);
}

}  // namespace

void TimeOfFlight::reset() { *this = TimeOfFlight{}; }

TofFrame& TimeOfFlight::push() {
  TofFrame& slot = ring_[head_];
  head_ = static_cast<uint16_t>((head_ + 1) % kTofFrames);
  if (count_ < kTofFrames) ++count_;
  return slot;
}

const TofFrame& TimeOfFlight::at(uint16_t back) const {
  return ring_[(head_ + kTofFrames - 1 - back) % kTofFrames];
}

bool TimeOfFlight::search(const TofTrackInput& in, int trail, int64_t want_ns, int64_t min_ns, int64_t max_ns,
                          Candidate& out) const {
  const int lead = 1 - trail;
  // Never for an acquisition (kTofWindowGateFrames: a periodic scene's aliases).
  const bool window = want_ns > 0 && track_frames_ >= kTofWindowGateFrames;
  const TofFrame& now = at(0);
  const TofFrame& before = at(1);
  // The trail camera's own change since its previous frame, Q48.
  int64_t motion = 0;
  for (uint8_t k = 0; k < in.count; ++k) {
    const int64_t d = fx::shr_round(int64_t{now.f[trail][k]} - before.f[trail][k], 4);
    motion += d * d;
  }
  bool found = false;
  int64_t best_dd = 1, best_span = 0;  // of the best segment, for its uncertainty ...
  int64_t best_fr = 0;                 // ... its place: the fraction along segment best_back ...
  bool best_inside = false;            // ... inside it (not at a frame), for its bend (chord_time)
  uint16_t best_back = 0;
  int32_t best_step[kMaxKernels];
  int64_t turned = 0;  // |rotation| summed frame by frame back to a (Q28): a turn that reverses does not cancel
  for (uint16_t back = 0; back + 1 < count_; ++back) {
    const TofFrame& b = at(back);
    const TofFrame& a = at(static_cast<uint16_t>(back + 1));
    turned += abs64(b.heading - a.heading);
    // Only segments whose time span reaches [min_ns, max_ns]; older ones lie further back.
    const int64_t lo = static_cast<int64_t>(now.t_ns - b.t_ns), hi = static_cast<int64_t>(now.t_ns - a.t_ns);
    if (lo > max_ns) break;
    if (hi < min_ns) continue;
    const int64_t dth = now.heading - (a.heading + b.heading) / 2;
    // Tracking: a segment whose whole span is no nearer to want_ns than the
    // best candidate so far cannot hold a better one.
    if (found && want_ns > 0) {
      const int64_t nearest = want_ns < lo ? lo - want_ns : (want_ns > hi ? want_ns - hi : 0);
      if (nearest >= abs64(abs64(out.stau_ns) - want_ns)) continue;
    }
    if (abs64(dth) > in.max_rotation) continue;
    // The lead's heading along the segment is interpolated with the point on
    // it: each of its frames is turned to the trail's heading, and the segment
    // runs between the turned frames. (With the segment's mean heading for
    // both, a turn of w over a frame moved the match by (fr - 1/2) w dt of
    // yaw, read as distance: h / tau 0.4-0.7 % off on the paper's 15 m arc.)
    // A frame step that turned more than twice max_rotation is not
    // interpolated; so both angles stay below 2^30 in Q28 (max_rotation <
    // 2^28) and each product below is one 32 x 32 -> 64 multiply; the
    // differences, in Q24, are held to the +-2^28 that two ValueQ28 can
    // differ by, so that each sum of kMaxKernels products stays below 2^62.
    const int64_t step_turn = b.heading - a.heading;
    if (abs64(step_turn) > 2 * int64_t{in.max_rotation}) continue;
    const auto dth_a = static_cast<int32_t>(now.heading - a.heading);
    const auto dth_ab = static_cast<int32_t>(step_turn);
    int64_t ee = 0, ed = 0, dd = 0;  // Q48
    int32_t step_q24[kMaxKernels];
    for (uint8_t k = 0; k < in.count; ++k) {
      // Turned by dtheta: F + dtheta * mean(dF/dtheta) (trail now, lead on the segment).
      const int32_t rb = static_cast<int32_t>(
          (int64_t{now.r[trail][k]} + (int64_t{a.r[lead][k]} + b.r[lead][k]) / 2) / 2);  // Q20
      const int64_t tv = int64_t{now.f[trail][k]} - fx::shr_round(int64_t{dth_a} * rb, fx::kSlopeFrac);  // Q28
      const int32_t e = static_cast<int32_t>(fx::clamp64(fx::shr_round(tv - a.f[lead][k], 4), -kDiffMaxQ24, kDiffMaxQ24));
      const int64_t step = int64_t{b.f[lead][k]} - a.f[lead][k] - fx::shr_round(int64_t{dth_ab} * rb, fx::kSlopeFrac);
      const int32_t d = static_cast<int32_t>(fx::clamp64(fx::shr_round(step, 4), -kDiffMaxQ24, kDiffMaxQ24));
      step_q24[k] = d;
      ee += int64_t{e} * e;
      ed += int64_t{e} * d;
      dd += int64_t{d} * d;
    }
    if (dd <= 0) continue;
    // The closest point on the segment, or its end where the point lies just
    // beyond it (kTofVertexSlack): the squared distance to a, or to b (ee - 2 ed + dd,
    // summed so that no partial sum passes 2^62).
    const int64_t slack = dd / kVertexSlackDiv;
    int64_t fr = 0, res = 0;
    bool inside = false;
    if (ed < 0) {
      if (ed < -slack) continue;
      res = ee;
    } else if (ed > dd) {
      if (ed - dd > slack) continue;
      fr = kOneQ16;
      res = (ee - ed) + (dd - ed);
    } else {
      fr = fx::fraction_q16(ed, dd);  // Q16 in [0, 1] (0 <= ed <= dd)
      res = ee - fx::shr_round(fr * ed, 16);
      inside = true;
    }
    if (res < 0) res = 0;
    if (res > (kMotionResidualSqQ16 * (motion >> 16))) continue;
    const int64_t span = static_cast<int64_t>(b.t_ns - a.t_ns);
    const int64_t t_lead = static_cast<int64_t>(a.t_ns) + ((span * fr) >> 16);
    const int64_t tau = static_cast<int64_t>(now.t_ns) - t_lead;
    if (tau <= 0) continue;
    if (res > (kPathResidualSqQ16 * (dd >> 16)) && (!window || !within_window_gate(res, dd, tau, span))) continue;
    const int64_t stau = trail == 0 ? tau : -tau;
    const bool better = !found || (want_ns > 0 ? abs64(tau - want_ns) < abs64(abs64(out.stau_ns) - want_ns) : res < out.res);
    if (!better) continue;
    found = true;
    out.stau_ns = stau;
    out.res = res;
    out.turn = static_cast<AngleQ28>(std::min<int64_t>(turned, fx::kInt32Max));
    best_dd = dd;
    best_span = span;
    best_fr = fr;
    best_inside = inside;
    best_back = back;
    for (uint8_t k = 0; k < in.count; ++k) best_step[k] = step_q24[k];
  }
  if (found) {
    const TofFrame& b = at(best_back);
    const TofFrame& a = at(static_cast<uint16_t>(best_back + 1));
    int64_t fr = best_fr;
    if (best_inside) {
      // The chosen point's time along its segment's bend (chord_time; the
      // choice and the gates took the chord's: the shift is at most
      // kTofChordMaxShift of a frame, and one segment's bend costs a division).
      const int64_t bent = chord_time(lead, best_back, in.count, best_step, best_dd, best_fr);
      const int64_t tau = static_cast<int64_t>(now.t_ns) - (static_cast<int64_t>(a.t_ns) + ((best_span * bent) >> 16));
      if (tau > 0) {
        out.stau_ns = trail == 0 ? tau : -tau;
        fr = bent;
      }
    }
    // Timing uncertainty: the residual over the segment's step, in frames, times the step.
    // (res / dd in Q32 up to half a step squared; beyond, where the window's gate
    // took the match, in Q16: at most kTofMaxPathResidualLong^2.)
    bool wide = false;
    const int32_t ratio_q32 = fx::div_q(out.res, best_dd, 32, &wide);
    const uint32_t sig_q16 = wide ? fx::isqrt32(static_cast<uint32_t>(fx::div_q(out.res, best_dd, 16))) << 8
                                  : fx::isqrt32(static_cast<uint32_t>(ratio_q32));
    out.sig_ns = (best_span * int64_t{sig_q16}) >> 16;
    // Under a frame: the stereo cubic's point where it meets the trail's F
    // closely against the step, blended with the chord's as its residual
    // grows, and its sigma alike (continuous in the residual: no switch
    // that the twins' last bits could throw).
    int64_t s = 0, cres = 0;
    if (best_inside && best_back == 0 && stereo_cubic(trail, in.count, fr, &s, &cres)) {
      const int64_t qr = cres >= best_dd ? kOneQ16 : fx::isqrt32(static_cast<uint32_t>(fx::div_q(cres, best_dd, 32)));
      if (qr < kCubicBlendQ16) {
        const int64_t w = qr <= kCubicTakeQ16 ? kOneQ16 : fx::div_q(kCubicBlendQ16 - qr, kCubicBlendQ16 - kCubicTakeQ16, 16);
        const int64_t moved = fr + ((w * (s - fr)) >> 16);
        const int64_t tau = static_cast<int64_t>(now.t_ns) - (static_cast<int64_t>(a.t_ns) + ((best_span * moved) >> 16));
        if (tau > 0) {
          out.stau_ns = trail == 0 ? tau : -tau;
          fr = moved;
          const int64_t cubic_sig = (((kCubicSigmaQ16 * qr) >> 16) * best_span) >> 16;
          if (cubic_sig < out.sig_ns) out.sig_ns += (w * (cubic_sig - out.sig_ns)) >> 16;
        }
      }
    }
    out.y_then = a.y + static_cast<TravelQ16Ns>((fx::travel_between(b.y, a.y) * fr) >> 16);
  }
  return found;
}

bool TimeOfFlight::stereo_cubic(int trail, uint8_t count, int64_t fr, int64_t* s_out, int64_t* res_out) const {
  // G(s) = A + g s + k s^2 + m s^3 over the newest segment (s its time, as
  // a fraction: a = 0, now = 1, the frame before = -1), each frame turned to
  // now's heading: G(1) = B, G(-1) = P, and G(0) - G(-u) = S_a, the stereo
  // difference at a (the trail, u = 1 - s behind, stood where the lead had
  // been). Then k = (d + e) / 2, m = -(S_a + k u^2 - (d - e) u / 2) / (u (1 - u^2)),
  // g = (d - e) / 2 - m with d = B - A, e = P - A; the point is where G(1 - u)
  // meets the trail's F now.
  if (count_ < 3) return false;
  const int lead = 1 - trail;
  const TofFrame& now = at(0);
  const TofFrame& a = at(1);
  const TofFrame& p = at(2);
  const int64_t span = static_cast<int64_t>(now.t_ns - a.t_ns), before = static_cast<int64_t>(a.t_ns - p.t_ns);
  if (span <= 0 || abs64(before - span) * 16 > span) return false;  // a frame dropped before the segment
  // Per kernel, Q24: k = (d + e) / 2 and h = (d - e) / 2 (< 2^27), S_a and the trail's F now, from A.
  int64_t kk[kMaxKernels], hh[kMaxKernels], sa[kMaxKernels], w[kMaxKernels];
  const auto dth_a = static_cast<int32_t>(now.heading - a.heading);
  const auto dth_p = static_cast<int32_t>(now.heading - p.heading);
  for (uint8_t k = 0; k < count; ++k) {
    const int32_t rb = static_cast<int32_t>(
        (int64_t{now.r[trail][k]} + (int64_t{a.r[lead][k]} + now.r[lead][k]) / 2) / 2);  // Q20, as search's
    const int64_t la = int64_t{a.f[lead][k]} + fx::shr_round(int64_t{dth_a} * rb, fx::kSlopeFrac);  // A, Q28
    const int64_t lp = int64_t{p.f[lead][k]} + fx::shr_round(int64_t{dth_p} * rb, fx::kSlopeFrac);  // P, Q28
    auto q24 = [](int64_t v) { return fx::clamp64(fx::shr_round(v, 4), -kCubicInMaxQ24, kCubicInMaxQ24); };
    const int64_t d = q24(int64_t{now.f[lead][k]} - la), e = q24(lp - la);
    kk[k] = (d + e) / 2;
    hh[k] = (d - e) / 2;
    sa[k] = q24(int64_t{a.f[lead][k]} - a.f[trail][k]);
    w[k] = q24(int64_t{now.f[trail][k]} - la);
  }
  // The squared residual at s (Q16), Q48.
  auto cost = [&](int64_t s16) {
    const int64_t s = s16 << 12, u = (kOneQ16 - s16) << 12;  // Q28
    const int64_t s2 = (s * s) >> 28, s3 = (s2 * s) >> 28, u2 = (u * u) >> 28;
    const int64_t den = u - ((u2 * u) >> 28);  // u (1 - u^2) >= 0.019 (Q28: > 2^22)
    const int64_t inv = fx::div_trunc(int64_t{1} << 56, den);  // 1 / den, Q28 (< 2^34): one division per point
    int64_t sum = 0;
    for (uint8_t k = 0; k < count; ++k) {
      const int64_t num = sa[k] + ((kk[k] * u2) >> 28) - ((hh[k] * u) >> 28);  // Q24, < 2^28
      const int64_t m = -((num * inv) >> 28);                                  // Q24, < 2^34
      const int64_t g = hh[k] - m;
      const int64_t r = fx::clamp64(((g * s) >> 28) + ((kk[k] * s2) >> 28) + ((m * s3) >> 28) - w[k], -(int64_t{1} << 30),
                                    int64_t{1} << 30);
      sum += r * r;  // < 2^60, kMaxKernels of them (a sum held below 2^62 below)
      if (sum > (int64_t{1} << 61)) sum = int64_t{1} << 61;
    }
    return sum;
  };
  const int64_t lo = kCubicEndsQ16, hi = kOneQ16 - kCubicEndsQ16;
  int64_t best = lo, best_cost = cost(lo);
  for (int i = 1; i <= kTofCubicGrid; ++i) {
    const int64_t s = lo + (hi - lo) * i / kTofCubicGrid;
    const int64_t c = cost(s);
    if (c < best_cost) {
      best = s;
      best_cost = c;
    }
  }
  // Parabolas about it: the vertex through (x - h, x, x + h), held to that
  // bracket, where the three are convex; else x stands.
  int64_t x = best, cx = best_cost, h = (hi - lo) / kTofCubicGrid;
  for (int i = 0; i < kTofCubicParabolas && h > 0; ++i) {
    const int64_t xm = std::max(lo, x - h), xp = std::min(hi, x + h);
    const int64_t cm = cost(xm), cp = cost(xp);
    const int64_t curv = (cm >> 1) + (cp >> 1) - cx;  // (c- - 2 c0 + c+) / 2, Q48
    if (xp - x == h && x - xm == h && curv > 0) {
      const int64_t off = fx::div_q((cm >> 2) - (cp >> 2), curv, 16);  // h units, Q16: (c- - c+) / (2 (c- - 2 c0 + c+))
      x = fx::clamp64(x + ((h * fx::clamp64(off, -kOneQ16, kOneQ16)) >> 16), xm, xp);
      cx = cost(x);
    } else if (cm < cx || cp < cx) {
      x = cm < cp ? xm : xp;
      cx = cm < cp ? cm : cp;
    }
    h /= kTofCubicShrink;
  }
  *s_out = x;
  *res_out = cx;
  return abs64(x - fr) <= kCubicMaxMoveQ16;
}

int64_t TimeOfFlight::chord_time(int lead, uint16_t back, uint8_t count, const int32_t* d, int64_t dd, int64_t fr) const {
  // On a path F(s) = a + d s + c s (1 - s) over the segment (s its time, as a
  // fraction), the closest point on the chord lies at s + (c . d / |d|^2) s (1 - s);
  // c = -D2 / 2 with D2 the path's second difference over a frame, taken at
  // the segment's newer end, or the mean with its older end's where that exists.
  // (The heading's own second difference, zero on a steady turn, is left out.)
  // Not on the newest segment (tau under a frame): there the travel per frame
  // outruns the finest texture and the second difference aliases
  // (`TimeOfFlight.FasterThanAFrame`: h / tau 3.1 % high with it).
  if (back == 0) return fr;
  const bool older = back + 2 < count_;
  const TofFrame& n = at(static_cast<uint16_t>(back - 1));
  const TofFrame& b = at(back);
  const TofFrame& a = at(static_cast<uint16_t>(back + 1));
  int64_t c2d = 0;  // Q44: D2 in Q20 (|.| < 2^26: four ValueQ28) times d in Q24 (< 2^28), kMaxKernels <= 64 terms
  for (uint8_t k = 0; k < count; ++k) {
    int64_t d2 = int64_t{a.f[lead][k]} - 2 * int64_t{b.f[lead][k]} + n.f[lead][k];  // Q28
    if (older) d2 += int64_t{at(static_cast<uint16_t>(back + 2)).f[lead][k]} - 2 * int64_t{a.f[lead][k]} + b.f[lead][k];
    c2d += fx::shr_round(d2, older ? 9 : 8) * d[k];
  }
  const int64_t den = dd >> 4;  // Q44
  if (den <= 0) return fr;
  bool sat = false;  // (a saturated ratio is held by the shift's bound below)
  const int64_t ratio = fx::div_q(c2d, 2 * den, 16, &sat);  // D2 . d / (2 |d|^2), Q16 (< 2^31)
  const int64_t s1s = (fr * (kOneQ16 - fr)) >> 16;          // s (1 - s) <= 2^14, Q16
  const int64_t shift = fx::clamp64((ratio * s1s) >> 16, -kChordMaxShiftQ16, kChordMaxShiftQ16);
  return fx::clamp64(fr + shift, 0, kOneQ16);
}

TofResult TimeOfFlight::track(const TofTrackInput& in) {
  TofResult r{};
  if (count_ < 3) {
    misses_ = 255;
    held_once_ = false;  // lost since the history began (lost_long below)
    return r;
  }
  const int64_t frame_ns = static_cast<int64_t>(at(0).t_ns - at(1).t_ns);
  Candidate pick{};
  bool have = false;
  if (misses_ < kTofTrackMisses) {
    Candidate c{};
    const int trail = track_ns_ > 0 ? 0 : 1;
    const int64_t want = abs64(track_ns_), g = gate_ns(want, frame_ns);
    if (search(in, trail, want, want - g, want + g, c) && abs64(abs64(c.stau_ns) - want) < g) {
      // A track past kTofMaxTau (not used by the fusion) that the fused V
      // runs against faster than kTofAcquireMinSpeed is dropped rather than
      // followed on: after a reversal the rig retraces its path, and each
      // camera finds the other's views from before it at a tau that grows by
      // two frames a frame; kept, such a track blocks the new direction's
      // acquisition. (A slow pass keeps its track; one the fusion uses is
      // never dropped so: the twins, deciding a frame apart, would blend it apart.)
      // A track against the images' direction of travel is an alias of a
      // repeating texture (stripes of 12 cm at h = 8 cm: 2 V the wrong way).
      if ((abs64(c.stau_ns) > kTofMaxTauNs && guiding(in.v_fused, c.stau_ns > 0 ? 1 : 0, in.baseline)) ||
          against_images(in.direction, c.stau_ns, in.baseline)) {
        misses_ = 255;
      } else {
        pick = c;
        have = true;
        if (track_frames_ < 255) ++track_frames_;
      }
    }
  }
  if (!have) {
    if (misses_ < 255) ++misses_;
    // (Re)acquisition: the best candidate that agrees with the fused velocity
    // or with this frame's direct value (the fused V lags an acceleration, and
    // reads low where the scale is not learned yet; the direct value does
    // neither but is noisier), confirmed over several frames. Above
    // kTofAcquireMinSpeed only the hints' directions and the taus that agree
    // with them are searched (the agreement is checked exactly below); with
    // no hint that fast, both directions, every usable tau. A hint against
    // the images' direction of travel guides nothing: with no other, the
    // search is unguided and takes kTofLostAcquireFrames.
    const int64_t hints[2] = {in.v_fused, in.v_direct};
    bool guided = false, contradicted = false;
    for (int64_t h : hints) {
      if (abs64(h) <= kAcquireMinSpeedQ16) continue;
      if (hint_against_images(in.direction, h)) contradicted = true; else guided = true;
    }
    const int64_t num = int64_t{in.baseline < 0 ? -in.baseline : in.baseline} * 1000000000;  // Q24 m ns
    // Lost long (kTofLostTime), or no track since the history began (nothing
    // has vouched for the hints): unguided as well where they agree with nothing.
    const bool lost_long = !held_once_ || at(0).t_ns - track_t_ns_ >= static_cast<uint64_t>(kLostNs);
    Candidate best{};
    bool any = false, unguided = false;
    for (int pass = 0; pass < 2 && !any; ++pass) {
      if (pass == 1 && !(guided && lost_long)) break;
      const bool g = pass == 0 && guided;
      for (int trail = 0; trail < 2; ++trail) {
        if (against_images(in.direction, trail == 0 ? 1 : -1, in.baseline)) continue;
        int64_t min_ns = g ? kTofMaxTauNs : 0, max_ns = g ? 0 : kTofMaxTauNs;
        for (int64_t h : hints) {
          if (!g || !guiding(h, trail, in.baseline)) continue;
          const int64_t fast = ((kOneQ16 + kAgreementQ16) * abs64(h)) >> 16, slow = ((kOneQ16 - kAgreementQ16) * abs64(h)) >> 16;
          min_ns = std::min<int64_t>(min_ns, int64_t{fx::div_q(num, fast * 256, 0)} - frame_ns);
          max_ns = std::max<int64_t>(max_ns, slow > 0 ? int64_t{fx::div_q(num, slow * 256, 0)} + frame_ns : kTofMaxTauNs);
        }
        max_ns = std::min<int64_t>(max_ns, kTofMaxTauNs);
        if (min_ns >= max_ns) continue;  // no hint in this direction
        Candidate c{};
        if (!search(in, trail, 0, min_ns, max_ns, c)) continue;
        const SpeedQ16 v = speed_of(in.baseline, c.stau_ns > 0 ? 1 : -1, abs64(c.stau_ns));
        bool agrees = !g;
        for (int64_t h : hints)
          agrees = agrees || (guiding(h, trail, in.baseline) && abs64(int64_t{v} - h) <= ((kAgreementQ16 * abs64(h)) >> 16));
        if (!agrees) continue;
        if (!any || c.res < best.res) {
          best = c;
          any = true;
        }
      }
      unguided = pass == 1 || (!g && contradicted);
    }
    if (any) {
      acquire_gap_ = 0;
      const bool same = acquire_count_ > 0 && (best.stau_ns > 0) == (acquire_ns_ > 0) &&
                        abs64(abs64(best.stau_ns) - abs64(acquire_ns_)) < gate_ns(acquire_ns_, frame_ns);
      acquire_count_ = same ? static_cast<uint8_t>(acquire_count_ + 1) : 1;
      acquire_ns_ = best.stau_ns;
      if (acquire_count_ >= (unguided ? kTofLostAcquireFrames : kTofAcquireFrames)) {
        pick = best;
        have = true;
        acquire_count_ = 0;
        track_frames_ = 0;
      }
    } else if (acquire_gap_ < kTofAcquireGapFrames) {
      ++acquire_gap_;  // (kTofAcquireGapFrames: the run stands)
    } else {
      acquire_count_ = 0;
    }
  }
  if (!have) {
    r.held = misses_ < kTofTrackMisses;
    return r;
  }
  track_ns_ = pick.stau_ns;
  track_t_ns_ = at(0).t_ns;
  held_once_ = true;
  misses_ = 0;
  r.ok = true;
  r.direction = pick.stau_ns > 0 ? 1 : -1;
  r.tau_ns = abs64(pick.stau_ns);
  r.v = speed_of(in.baseline, r.direction, r.tau_ns);
  r.sig = fx::div_q(pick.sig_ns, r.tau_ns, fx::kFracFrac);
  r.y_then = pick.y_then;
  r.turn = pick.turn;
  r.frames = track_frames_;
  return r;
}

}  // namespace lumavel
