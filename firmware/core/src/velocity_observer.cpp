#include "lumavel/core/velocity_observer.hpp"

#include "lumavel/core/estimator_params.hpp"
#include "lumavel/core/imath.hpp"

namespace lumavel {
namespace {

constexpr int32_t kClampQ28 = int32_t{1} << 30;  // |values| <= 4 keep sums of squares in int64

int32_t clamp4(int64_t v, bool* sat) {
  if (v > kClampQ28) {
    *sat = true;
    return kClampQ28;
  }
  if (v < -kClampQ28) {
    *sat = true;
    return -kClampQ28;
  }
  return static_cast<int32_t>(v);
}

// The clamp of x (estimator_params.hpp), Q28 rad.
constexpr int64_t kMaxHalfPhaseQ28 = fx::q_of(params::kMaxHalfPhase, 28);

// x / tan(x) for |x| <= kMaxHalfPhase (clamped, 1.2 rad), Q1.30, by its series
// 1 - x^2/3 - x^4/45 - 2x^6/945 - x^8/4725 - 2x^10/93555 (error < 3e-5 at 1.2).
// 32-bit operands, so that each product is one 32 x 32 -> 64 multiply: the
// clamped x (< 1.2 2^28), x^2 (< 1.45 2^30), each Horner partial (|p| < 0.38
// 2^30) and the result (in (0.4, 1] 2^30) all fit int32.
int32_t x_over_tan_q30(int64_t x_q28) {
  const int64_t lim = kMaxHalfPhaseQ28;
  if (x_q28 > lim) x_q28 = lim;
  if (x_q28 < -lim) x_q28 = -lim;
  const auto x = static_cast<int32_t>(x_q28);
  const auto x2 = static_cast<int32_t>(fx::shr_round(int64_t{x} * x, 26));  // Q30
  // Horner in x^2 from the highest term.
  const int64_t one = int64_t{1} << 30;
  const auto horner = [x2](int32_t p, int64_t c) { return static_cast<int32_t>(fx::shr_round(int64_t{p} * x2, 30) - c); };
  auto p = static_cast<int32_t>(-(2 * one) / 93555);
  p = horner(p, one / 4725);
  p = horner(p, (2 * one) / 945);
  p = horner(p, one / 45);
  p = horner(p, one / 3);
  return static_cast<int32_t>(one + fx::shr_round(int64_t{p} * x2, 30));
}

// |e - ratio a|^2 / |e|^2 (ratio Q28): how much of the innovation the one
// distance leaves unexplained. Products in Q48 (values brought to Q24: six
// kernels of |.| <= 4 stay inside int64).
FracQ16 residual_ratio(const int32_t* e, const int32_t* a, uint8_t count, int32_t ratio) {
  int64_t rr = 0, ee = 0;
  for (uint8_t k = 0; k < count; ++k) {
    const int64_t ek = fx::shr_round(e[k], 4);
    const int64_t rk = ek - fx::shr_round(int64_t{ratio} * fx::shr_round(a[k], 4), fx::kValueFrac);
    rr += rk * rk;
    ee += ek * ek;
  }
  if (ee <= 0) return 0;
  const int64_t q = fx::div_q(rr, ee, fx::kFracFrac);
  return static_cast<FracQ16>(q > (int64_t{1} << fx::kFracFrac) ? (int64_t{1} << fx::kFracFrac) : q);
}

// The finite step in time (header): the ratio d / h that explains e once each
// kernel's innovation is scaled by y / tan(y), y = x_k d / h. One evaluation
// of that map at `ratio` (Q28), over the products' common denominator.
int32_t step_corrected_ratio(const int32_t* e, const int32_t* a, const int32_t* half, uint8_t count, int32_t ratio,
                             int64_t den, bool* sat) {
  int64_t num = 0;  // Q56
  for (uint8_t k = 0; k < count; ++k) {
    const int64_t y = fx::shr_round(int64_t{half[k]} * ratio, fx::kValueFrac);
    // (|e x/tan x| <= |e|: int32)
    num += int64_t{static_cast<int32_t>(fx::shr_round(int64_t{e[k]} * x_over_tan_q30(y), 30))} * a[k];
  }
  return fx::div_q(num, den, fx::kValueFrac, sat);
}

// Its fixed point: two evaluations and Aitken's extrapolation. The map falls
// as the ratio grows (a longer step, a stronger correction), so its iterates
// alternate about the fixed point, which lies between the last two: the
// extrapolation is taken only then (else the second iterate).
int32_t solve_step_correction(const int32_t* e, const int32_t* a, const int32_t* half, uint8_t count, int32_t r0,
                              int64_t den, bool* sat) {
  const int32_t r1 = step_corrected_ratio(e, a, half, count, r0, den, sat);
  const int32_t r2 = step_corrected_ratio(e, a, half, count, r1, den, sat);
  const int64_t d1 = int64_t{r1} - r0, d2 = int64_t{r2} - r1;
  if ((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) {
    // |d2 - d1| > |d2|: the step d2^2 / (d2 - d1) is below |d2| (|d2| < 2^32: d2^2 < 2^64 as unsigned).
    const uint64_t ad2 = static_cast<uint64_t>(d2 < 0 ? -d2 : d2), ad = static_cast<uint64_t>(d2 > d1 ? d2 - d1 : d1 - d2);
    const int64_t step = static_cast<int64_t>((ad2 * ad2 + ad / 2) / ad);
    return static_cast<int32_t>(d2 > 0 ? int64_t{r2} - step : int64_t{r2} + step);
  }
  return r2;
}

}  // namespace

void VelocityObserver::reset() { *this = VelocityObserver{}; }

ObserverOutput VelocityObserver::update(const ObserverInput& in) {
  ObserverOutput out{};
  tau_us_ = in.tau_us;
  bool sat = false;
  const uint8_t count = in.cur->count;
  int32_t s_bar[kMaxKernels], e[kMaxKernels];
  int64_t ss = 0, ss_cur = 0, ss_prev = 0;  // Q56
  for (uint8_t k = 0; k < count; ++k) {
    const int64_t d_mid = int64_t{in.cur->mid[k]} - in.prev->mid[k];
    s_bar[k] = clamp4(fx::shr_round(int64_t{in.cur->diff[k]} + in.prev->diff[k], 1), &sat);
    const int64_t r_bar = fx::shr_round(int64_t{in.cur->rot[k]} + in.prev->rot[k], 1);
    // Innovation with the rotation term removed: Q28.
    e[k] = clamp4(d_mid - fx::shr_round(int64_t{in.dtheta} * r_bar, fx::kSlopeFrac), &sat);
    ss += int64_t{s_bar[k]} * s_bar[k];
    const int64_t sc = clamp4(in.cur->diff[k], &sat), sp = clamp4(in.prev->diff[k], &sat);
    ss_cur += sc * sc;
    ss_prev += sp * sp;
  }
  // Observability of the interval: the weaker of its two frames, so that
  // texture appearing or vanishing between frames (lights, occlusion) is not
  // read as motion.
  const int64_t ss_min = ss_cur < ss_prev ? ss_cur : ss_prev;
  out.texture = count ? static_cast<ValueQ28>(fx::isqrt64(fx::udiv_trunc(static_cast<uint64_t>(ss_min), count))) : 0;
  int64_t num = 0, den = 0;  // Q56
  int32_t a_used[kMaxKernels];
  int32_t half[kMaxKernels];  // x_k, Q28
  for (uint8_t k = 0; k < count; ++k) {
    int32_t a = s_bar[k];
    if (in.baseline_correction) {
      half[k] = static_cast<int32_t>(fx::shr_round(int64_t{in.cur->half_phase[k]} + in.prev->half_phase[k], 1));
      a = static_cast<int32_t>(fx::shr_round(int64_t{a} * x_over_tan_q30(half[k]), 30));
    }
    a_used[k] = a;
    num += int64_t{e[k]} * a;
    den += int64_t{a} * a;
  }
  if (count == 0 || den == 0 || ss == 0 || out.texture < in.low_texture || in.dt_ns <= 0) {
    out.v = v_;
    out.updated = false;
    out.converging = converging_now();
    return out;
  }
  // Distance over the interval: d = h * num / den.
  int32_t ratio = fx::div_q(num, den, fx::kValueFrac, &sat);  // Q28
  if (in.baseline_correction) {
    ratio = solve_step_correction(e, a_used, half, count, ratio, den, &sat);
    // (the residual of the model as corrected)
    for (uint8_t k = 0; k < count; ++k)
      e[k] = static_cast<int32_t>(
          fx::shr_round(int64_t{e[k]} * x_over_tan_q30(fx::shr_round(int64_t{half[k]} * ratio, fx::kValueFrac)), 30));
  }
  const int64_t d_q24 = fx::shr_round(int64_t{ratio} * in.baseline, fx::kValueFrac);       // Q24 m
  const SpeedQ16 v_direct = fx::div_q(d_q24 * 1000000000, in.dt_ns * 256, 0, &sat);       // Q16 m/s
  out.v_direct = v_direct;
  out.residual = residual_ratio(e, a_used, count, ratio);
  if (!started_) {
    v_ = v_direct;
    started_ = true;
    since_start_us_ = 0;
    tau_now_us_ = young_time_constant_us(since_start_us_, in.tau_us);
  } else {
    const int64_t dt_us = fx::div_trunc(in.dt_ns, 1000);
    since_start_us_ += dt_us;
    tau_now_us_ = young_time_constant_us(since_start_us_, in.tau_us);
    v_ = observer_step(v_, v_direct, dt_us, tau_now_us_, &sat);
  }
  out.v = v_;
  out.updated = true;
  out.saturated = sat;
  out.converging = converging_now();
  return out;
}

}  // namespace lumavel
