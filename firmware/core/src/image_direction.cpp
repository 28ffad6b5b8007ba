#include "lumavel/core/image_direction.hpp"

#include "lumavel/core/fusion_params.hpp"
#include "lumavel/core/imath.hpp"

namespace lumavel {
namespace {

constexpr int64_t kTauNs = fx::q_of(params::kImageDirectionTau * 1e9, 0);
constexpr int64_t kMinRateQ24 = fx::q_of(params::kImageDirectionMinRate, 24);
constexpr int64_t kSigmas2Q4 = fx::q_of(params::kImageDirectionSigmas * params::kImageDirectionSigmas, 4);
constexpr int64_t kRateMaxQ24 = int64_t{64} << 24;
constexpr int64_t kMinLookQ30 = fx::q_of(params::kImageDirectionMinLook, 30);

}  // namespace

void ImageDirection::update(const StereoMeasurement& prev, const StereoMeasurement& cur, AngleQ28 dtheta,
                            int64_t dt_ns, int8_t look) {
  if (look == 0 || dt_ns <= 0) {
    direction_ = 0;
    return;
  }
  // (dF - dtheta Rbar) in Q24 and Rbar in Q16: products below 2^54, 2 kMaxKernels of them below 2^58.
  int64_t num = 0, den = 0;
  for (int i = 0; i < 2; ++i)
    for (uint8_t k = 0; k < cur.count; ++k) {
      const int64_t rb = (int64_t{cur.r[i][k]} + prev.r[i][k]) / 2;  // Q20
      const int64_t turn = fx::shr_round(int64_t{dtheta} * rb, fx::kSlopeFrac);  // Q28 (|dtheta| < 2^31, |rb| < 2^31)
      const int64_t e = fx::clamp64(fx::shr_round(int64_t{cur.f[i][k]} - prev.f[i][k] - turn, 4), -(int64_t{1} << 27),
                                int64_t{1} << 27);  // Q24
      const int64_t r = fx::shr_round(rb, 4);  // Q16
      num += e * r;                            // Q40
      den += r * r;                            // Q32
    }
  if (den == 0) return;  // nothing to read: the state stands
  // The yaw the images moved by (Q28 rad: Q40 / Q32 -> Q8, so 20 more), then
  // per second, signed as V: a left-looking camera's view moves against it.
  const int64_t yaw = fx::div_q(num, den, 20);
  const int64_t rate = fx::clamp64(fx::div_q(-look * yaw * 1000000000, dt_ns * 16, 0), -kRateMaxQ24, kRateMaxQ24);
  const int64_t a = dt_ns >= kTauNs ? int64_t{1} << 16 : (dt_ns << 16) / kTauNs;  // Q16
  mean_ = static_cast<RateQ24>(mean_ + fx::shr_round((rate - mean_) * a, 16));
  const int64_t dev = rate - mean_;  // |.| < 2^31: its square below 2^62
  var_ += fx::shr_round(dev * dev - var_, 16) * a;
  // (beyond 2^58, k^2 var passes any mean's square: no direction)
  const int64_t m = mean_;
  const bool clear = (m > kMinRateQ24 || m < -kMinRateQ24) && var_ < (int64_t{1} << 58) &&
                     m * m > (var_ >> 4) * kSigmas2Q4;
  direction_ = clear ? (m > 0 ? 1 : -1) : 0;
}

bool ImageDirection::against(SpeedQ16 v) const {
  constexpr int64_t kFlagSpeedQ16 = fx::q_of(params::kImageDirectionFlagSpeed, 16);
  return (direction_ > 0 && v < -kFlagSpeedQ16) || (direction_ < 0 && v > kFlagSpeedQ16);
}

int8_t image_look(const CameraGeometry& cam0, const CameraGeometry& cam1) {
  constexpr int32_t kHalfPiQ28 = static_cast<int32_t>(fx::kPiQ28 / 2);
  const int64_t sines = int64_t{fx::cos_q30(cam0.axis_yaw - kHalfPiQ28)} + fx::cos_q30(cam1.axis_yaw - kHalfPiQ28);
  if (sines >= 2 * kMinLookQ30) return 1;
  if (sines <= -2 * kMinLookQ30) return -1;
  return 0;
}

}  // namespace lumavel
