// Twin of firmware/core/src/time_of_flight.cpp.
#include "lumavel/host/float_time_of_flight.hpp"

#include <algorithm>
#include <cmath>

#include "lumavel/core/fusion_params.hpp"
#include "lumavel/core/limits.hpp"

namespace lumavel::host {
namespace {

using namespace params;

double gate_ns(double tau_ns, double frame_ns) {
  return std::max(kTofTrackGateFrames * frame_ns, kTofTrackGateFraction * std::fabs(tau_ns));
}

// (the core's against_images)
bool against_images(int direction, double stau_ns, double h) {
  return direction != 0 && ((stau_ns > 0) == (h > 0)) != (direction > 0);
}

// (the core's hint_against_images)
bool hint_against_images(int direction, double v_hint) { return direction != 0 && (v_hint > 0) != (direction > 0); }

// (the core's guiding)
bool guiding(double v_hint, int trail, double h) {
  return std::fabs(v_hint) > kTofAcquireMinSpeed && (trail == 0) == ((v_hint > 0) == (h > 0));
}

}  // namespace

void FloatTimeOfFlight::reset() { *this = FloatTimeOfFlight{}; }

void FloatTimeOfFlight::push(const FloatTofFrame& frame) {
  if (ring_.size() == static_cast<size_t>(kTofFrames)) ring_.erase(ring_.begin());
  ring_.push_back(frame);
}

const FloatTofFrame& FloatTimeOfFlight::at(size_t back) const { return ring_[ring_.size() - 1 - back]; }

bool FloatTimeOfFlight::search(int trail, double max_rotation, double want_ns, double min_ns, double max_ns,
                               Candidate& out) const {
  const int lead = 1 - trail;
  const bool window = want_ns > 0 && track_frames_ >= kTofWindowGateFrames;  // (the core's comment)
  const FloatTofFrame& now = at(0);
  const FloatTofFrame& before = at(1);
  const double motion = (now.f[trail] - before.f[trail]).squaredNorm();
  double best_fr = 0, best_dd = 1, best_span = 0;  // the chosen point's chord (the core's)
  bool best_inside = false;
  size_t best_back = 0;
  Eigen::VectorXd best_step;
  bool found = false;
  double turned = 0;  // as the core: a turn that reverses does not cancel
  for (size_t back = 0; back + 1 < ring_.size(); ++back) {
    const FloatTofFrame& b = at(back);
    const FloatTofFrame& a = at(back + 1);
    turned += std::fabs(b.heading - a.heading);
    const double lo = static_cast<double>(now.t_ns - b.t_ns), hi = static_cast<double>(now.t_ns - a.t_ns);
    if (lo > max_ns) break;
    if (hi < min_ns) continue;
    if (found && want_ns > 0) {  // pruned as in the core: no nearer candidate in this span
      const double nearest = want_ns < lo ? lo - want_ns : (want_ns > hi ? want_ns - hi : 0);
      if (nearest >= std::fabs(std::fabs(out.stau_ns) - want_ns)) continue;
    }
    const double dth = now.heading - (a.heading + b.heading) / 2;
    if (std::fabs(dth) > max_rotation) continue;
    // The lead's frames each turned to the trail's heading (the core's comment).
    const double step_turn = b.heading - a.heading;
    if (std::fabs(step_turn) > 2 * max_rotation) continue;
    const Eigen::VectorXd rb = (now.r[trail] + (a.r[lead] + b.r[lead]) / 2) / 2;
    const Eigen::VectorXd e = now.f[trail] - (now.heading - a.heading) * rb - a.f[lead];
    const Eigen::VectorXd d = b.f[lead] - a.f[lead] - step_turn * rb;
    const double ee = e.squaredNorm(), ed = e.dot(d), dd = d.squaredNorm();
    if (dd <= 0) continue;
    // The closest point, or the segment's end just beyond it (the core's comment).
    const double slack = dd * kTofVertexSlack;
    if (ed < -slack || ed - dd > slack) continue;
    const double fr = std::clamp(ed / dd, 0.0, 1.0);
    const double res = std::max(ed < 0 ? ee : (ed > dd ? ee - 2 * ed + dd : ee - fr * ed), 0.0);
    const bool inside = !(ed < 0 || ed > dd);  // (the chord's bend, below)
    if (res > kTofMaxResidualVsMotion * kTofMaxResidualVsMotion * motion) continue;
    const double span = static_cast<double>(b.t_ns - a.t_ns);
    const double tau = static_cast<double>(now.t_ns) - (static_cast<double>(a.t_ns) + span * fr);
    if (tau <= 0) continue;
    // The step's gate, or the window's where that is wider (the core's comment).
    const double gate = !window ? kTofMaxPathResidual
                                : std::max(kTofMaxPathResidual, std::min(kTofMaxTauShift * tau / span, kTofMaxPathResidualLong));
    if (res > gate * gate * dd) continue;
    const double stau = trail == 0 ? tau : -tau;
    const bool better = !found || (want_ns > 0 ? std::fabs(tau - want_ns) < std::fabs(std::fabs(out.stau_ns) - want_ns)
                                               : res < out.res);
    if (!better) continue;
    found = true;
    out.stau_ns = stau;
    out.res = res;
    out.sig_ns = span * std::sqrt(res / dd);
    out.turn = turned;
    best_fr = fr;
    best_inside = inside;
    best_back = back;
    best_step = d;
    best_dd = dd;
    best_span = span;
  }
  if (found) {
    const FloatTofFrame& b = at(best_back);
    const FloatTofFrame& a = at(best_back + 1);
    double fr = best_fr;
    if (best_inside) {  // the chosen point's time along its bend (the core's comment)
      const double bent = chord_time(lead, best_back, best_step, best_dd, best_fr);
      const double tau = static_cast<double>(now.t_ns) - (static_cast<double>(a.t_ns) + best_span * bent);
      if (tau > 0) {
        out.stau_ns = trail == 0 ? tau : -tau;
        fr = bent;
      }
    }
    // Under a frame: the stereo cubic's point, blended with the chord's, and its sigma alike (the core's comment).
    double s = 0, cres = 0;
    if (best_inside && best_back == 0 && stereo_cubic(trail, fr, &s, &cres)) {
      const double qr = std::sqrt(std::min(cres / best_dd, 1.0));
      if (qr < kTofCubicBlend) {
        const double w = qr <= kTofCubicTake ? 1.0 : (kTofCubicBlend - qr) / (kTofCubicBlend - kTofCubicTake);
        const double moved = fr + w * (s - fr);
        const double tau = static_cast<double>(now.t_ns) - (static_cast<double>(a.t_ns) + best_span * moved);
        if (tau > 0) {
          out.stau_ns = trail == 0 ? tau : -tau;
          fr = moved;
          const double cubic_sig = kTofCubicSigma * qr * best_span;
          if (cubic_sig < out.sig_ns) out.sig_ns += w * (cubic_sig - out.sig_ns);
        }
      }
    }
    out.y_then = a.y + fr * (b.y - a.y);
  }
  return found;
}

bool FloatTimeOfFlight::stereo_cubic(int trail, double fr, double* s_out, double* res_out) const {
  // The cubic through the lead's last three frames (the core's comment), its
  // fraction searched on the core's Q16 grid.
  if (ring_.size() < 3) return false;
  const int lead = 1 - trail;
  const FloatTofFrame& now = at(0);
  const FloatTofFrame& a = at(1);
  const FloatTofFrame& p = at(2);
  const int64_t span = static_cast<int64_t>(now.t_ns - a.t_ns), before = static_cast<int64_t>(a.t_ns - p.t_ns);
  if (span <= 0 || std::llabs(before - span) * 16 > span) return false;
  const Eigen::VectorXd rb = (now.r[trail] + (a.r[lead] + now.r[lead]) / 2) / 2;
  const Eigen::VectorXd la = a.f[lead] + (now.heading - a.heading) * rb;
  const Eigen::VectorXd lp = p.f[lead] + (now.heading - p.heading) * rb;
  auto held = [](Eigen::VectorXd v) { return v.cwiseMax(-4.0).cwiseMin(4.0); };  // (the core's clamp)
  const Eigen::VectorXd d = held(now.f[lead] - la), e = held(lp - la), sa = held(a.f[lead] - a.f[trail]),
                        w = held(now.f[trail] - la);
  const Eigen::VectorXd kk = (d + e) / 2, hh = (d - e) / 2;
  auto cost = [&](int64_t s16) {
    const double s = static_cast<double>(s16) / 65536, u = 1 - s;
    const Eigen::VectorXd m = -(sa + kk * u * u - hh * u) / (u * (1 - u * u));
    const Eigen::VectorXd g = hh - m;
    return (g * s + kk * s * s + m * s * s * s - w).cwiseMax(-64.0).cwiseMin(64.0).squaredNorm();
  };
  // The grid, as the core's (integer fractions, Q16).
  const int64_t one = 65536, ends = std::llround(kTofCubicEnds * 65536);
  const int64_t lo = ends, hi = one - ends;  // (a grid that does not move with fr: the core's comment)
  int64_t best = lo;
  double best_cost = cost(lo);
  for (int i = 1; i <= kTofCubicGrid; ++i) {
    const int64_t s = lo + (hi - lo) * i / kTofCubicGrid;
    const double c = cost(s);
    if (c < best_cost) {
      best = s;
      best_cost = c;
    }
  }
  // Parabolas about it (the core's comment), the points on the core's integer fractions.
  int64_t x = best, h = (hi - lo) / kTofCubicGrid;
  double cx = best_cost;
  for (int i = 0; i < kTofCubicParabolas && h > 0; ++i) {
    const int64_t xm = std::max(lo, x - h), xp = std::min(hi, x + h);
    const double cm = cost(xm), cp = cost(xp);
    const double curv = (cm + cp) / 2 - cx;
    if (xp - x == h && x - xm == h && curv > 0) {
      const double off = std::clamp((cm - cp) / 4 / curv, -1.0, 1.0);
      x = std::clamp(x + static_cast<int64_t>(std::floor(static_cast<double>(h) * off)), xm, xp);
      cx = cost(x);
    } else if (cm < cx || cp < cx) {
      x = cm < cp ? xm : xp;
      cx = cm < cp ? cm : cp;
    }
    h /= kTofCubicShrink;
  }
  *s_out = static_cast<double>(x) / 65536;
  *res_out = cx;
  return std::fabs(*s_out - fr) <= kTofCubicMaxMove;
}

double FloatTimeOfFlight::chord_time(int lead, size_t back, const Eigen::VectorXd& d, double dd, double fr) const {
  // The path's bend between the frames (the core's comment).
  if (back == 0) return fr;  // not on the newest segment (the core's comment)
  const Eigen::VectorXd& a = at(back + 1).f[lead];
  const Eigen::VectorXd& b = at(back).f[lead];
  Eigen::VectorXd d2 = a - 2 * b + at(back - 1).f[lead];
  if (back + 2 < ring_.size()) d2 = (d2 + at(back + 2).f[lead] - 2 * a + b) / 2;
  const double shift = std::clamp(d2.dot(d) / (2 * dd) * fr * (1 - fr), -kTofChordMaxShift, kTofChordMaxShift);
  return std::clamp(fr + shift, 0.0, 1.0);
}

FloatTofResult FloatTimeOfFlight::track(int direction, double baseline, double max_rotation, double v_fused, double v_direct) {
  FloatTofResult r;
  if (ring_.size() < 3) {
    misses_ = 255;
    held_once_ = false;  // lost since the history began (the core's)
    return r;
  }
  const double frame_ns = static_cast<double>(at(0).t_ns - at(1).t_ns);
  Candidate pick;
  bool have = false;
  if (misses_ < kTofTrackMisses) {
    Candidate c;
    const int trail = track_ns_ > 0 ? 0 : 1;
    const double want = std::fabs(track_ns_), g = gate_ns(want, frame_ns);
    if (search(trail, max_rotation, want, want - g, want + g, c) && std::fabs(std::fabs(c.stau_ns) - want) < g) {
      // Past kTofMaxTau and the fused V against it: dropped (the core's comment).
      // ... and one against the images' direction (the core's comment).
      if ((std::fabs(c.stau_ns) > kTofMaxTau * 1e9 && guiding(v_fused, c.stau_ns > 0 ? 1 : 0, baseline)) ||
          against_images(direction, c.stau_ns, baseline)) {
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
    // (The core's comment: a new track agrees with the fused V or the direct value.)
    const double hints[2] = {v_fused, v_direct};
    bool guided = false, contradicted = false;
    for (double h : hints) {
      if (std::fabs(h) <= kTofAcquireMinSpeed) continue;
      if (hint_against_images(direction, h)) contradicted = true; else guided = true;
    }
    const double num = std::fabs(baseline) * 1e9;
    // Lost long, or no track since the history began: unguided as well where the hints agree with nothing (the core's comment).
    const bool lost_long = !held_once_ || at(0).t_ns - track_t_ns_ >= static_cast<uint64_t>(std::llround(kTofLostTime * 1e9));
    Candidate best;
    bool any = false, unguided = false;
    for (int pass = 0; pass < 2 && !any; ++pass) {
      if (pass == 1 && !(guided && lost_long)) break;
      const bool g = pass == 0 && guided;
      for (int trail = 0; trail < 2; ++trail) {
        if (against_images(direction, trail == 0 ? 1 : -1, baseline)) continue;
        double min_ns = g ? kTofMaxTau * 1e9 : 0, max_ns = g ? 0 : kTofMaxTau * 1e9;
        for (double h : hints) {
          if (!g || !guiding(h, trail, baseline)) continue;
          min_ns = std::min(min_ns, num / ((1 + kTofAcquireAgreement) * std::fabs(h)) - frame_ns);
          max_ns = std::max(max_ns, num / ((1 - kTofAcquireAgreement) * std::fabs(h)) + frame_ns);
        }
        max_ns = std::min(max_ns, kTofMaxTau * 1e9);
        if (min_ns >= max_ns) continue;
        Candidate c;
        if (!search(trail, max_rotation, 0, min_ns, max_ns, c)) continue;
        const double v = (c.stau_ns > 0 ? baseline : -baseline) * 1e9 / std::fabs(c.stau_ns);
        bool agrees = !g;
        for (double h : hints) agrees = agrees || (guiding(h, trail, baseline) && std::fabs(v - h) <= kTofAcquireAgreement * std::fabs(h));
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
                        std::fabs(std::fabs(best.stau_ns) - std::fabs(acquire_ns_)) < gate_ns(acquire_ns_, frame_ns);
      acquire_count_ = same ? acquire_count_ + 1 : 1;
      acquire_ns_ = best.stau_ns;
      if (acquire_count_ >= (unguided ? kTofLostAcquireFrames : kTofAcquireFrames)) {
        pick = best;
        have = true;
        acquire_count_ = 0;
        track_frames_ = 0;
      }
    } else if (acquire_gap_ < kTofAcquireGapFrames) {
      ++acquire_gap_;
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
  r.tau_ns = std::fabs(pick.stau_ns);
  r.v = r.direction * baseline * 1e9 / r.tau_ns;
  r.sig = pick.sig_ns / r.tau_ns;
  r.y_then = pick.y_then;
  r.turn = pick.turn;
  r.frames = track_frames_;
  return r;
}

}  // namespace lumavel::host
