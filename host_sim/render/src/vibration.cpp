#include "lumavel/host/render/vibration.hpp"

#include <cmath>

#include "lumavel/host/render/random.hpp"

namespace lumavel::host::render {
namespace {
constexpr double kPi = 3.14159265358979323846;
}  // namespace

Vibration::Vibration(const VibrationSpec& spec, uint64_t seed) : none_(spec.none()) {
  if (none_) return;
  const double rms[3] = {spec.pitch_rms_deg * kPi / 180.0, spec.roll_rms_deg * kPi / 180.0, spec.heave_rms_m};
  Axis* axes[3] = {&pitch_, &roll_, &heave_};
  const double lo = spec.freq_lo_hz, hi = spec.freq_hi_hz;
  for (int k = 0; k < 3; ++k) {
    Rng rng(stream_seed(seed, 7, static_cast<uint64_t>(k)));
    // A band of one frequency is one tone (tones of equal frequency would
    // add to an rms that depends on their phases); otherwise the band is cut
    // in kVibrationTones geometric strata, a tone in the middle half of each,
    // so no two tones beat slowly and the rms holds over a few seconds.
    const int n = lo == hi ? 1 : kVibrationTones;
    for (int i = 0; i < n; ++i) {
      const double u = rng.uniform(), phase = 2 * kPi * rng.uniform();
      Tone& t = (*axes[k])[static_cast<size_t>(i)];
      t.amplitude = rms[k] * std::sqrt(2.0 / n);  // n tones of rms a / sqrt(2) each
      t.omega = 2 * kPi * lo * std::pow(hi / lo, (i + 0.25 + 0.5 * u) / n);
      t.phase = phase;
    }
  }
}

void Vibration::eval(const Axis& a, double t, double& v, double& dv, double& ddv) {
  v = dv = ddv = 0;
  for (const Tone& x : a) {
    if (x.amplitude == 0.0) continue;
    const double s = std::sin(x.omega * t + x.phase), c = std::cos(x.omega * t + x.phase);
    v += x.amplitude * s;
    dv += x.amplitude * x.omega * c;
    ddv -= x.amplitude * x.omega * x.omega * s;
  }
}

VibrationState Vibration::at(double t) const {
  VibrationState s;
  if (none_) return s;
  double unused = 0;
  eval(pitch_, t, s.pitch, s.pitch_rate, unused);
  eval(roll_, t, s.roll, s.roll_rate, unused);
  eval(heave_, t, s.heave, s.heave_rate, s.heave_accel);
  return s;
}

}  // namespace lumavel::host::render
