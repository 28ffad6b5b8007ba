#include "pillar_scene.hpp"

#include <array>
#include <cmath>

#include "left_rig.hpp"

namespace lumavel::soak {

namespace {

constexpr double kPi = 3.14159265358979323846;

// Texture around the pillar: 128 + sum a sin(n psi + p), psi the pillar's
// polar angle; wavelengths 0.37, 0.23 and 0.71 m on an 18 m pillar.
struct Wave {
  double amplitude;
  unsigned periods;  // < 512: z^n from z^1 .. z^256
  double phase;
};
constexpr std::array<Wave, 3> kWaves = {{{45, 306, 0.0}, {30, 492, 1.3}, {20, 159, 0.4}}};
const std::array<Phasor, 3> kPhasors = {Phasor{std::cos(kWaves[0].phase), std::sin(kWaves[0].phase)},
                                         Phasor{std::cos(kWaves[1].phase), std::sin(kWaves[1].phase)},
                                         Phasor{std::cos(kWaves[2].phase), std::sin(kWaves[2].phase)}};

// 4096 standard normal samples (Box-Muller on a 64-bit LCG, built once).
const std::array<double, 4096>& normal_table() {
  static const std::array<double, 4096> t = [] {
    std::array<double, 4096> v{};
    uint64_t s = 99;
    auto uni = [&s] {
      s = s * 6364136223846793005ull + 1442695040888963407ull;
      return (static_cast<double>(s >> 11) + 0.5) / 9007199254740992.0;
    };
    for (double& x : v) x = std::sqrt(-2 * std::log(uni())) * std::cos(2 * kPi * uni());
    return v;
  }();
  return t;
}

}  // namespace

double PillarScene::fu() const { return test::left_rig_fu(width, hfov); }
double PillarScene::axis(int cam) const { return test::left_rig_axis(cam, misalignment); }

host::EstimatorSettings PillarScene::settings() const {
  host::EstimatorSettings s = test::left_rig_settings(width, height, hfov, baseline, misalignment);
  s.frame_period = 1.0 / 60;
  return s;
}

double PillarScene::noise_sample() {
  seed = seed * 6364136223846793005ull + 1442695040888963407ull;
  return normal_table()[(seed >> 52) & 4095u];
}

void PillarScene::render_camera(int cam, double s, double gain, std::vector<uint8_t>& out) {
  const double R = path_radius, Rp = path_radius - distance;
  const double phi = s / R, theta = phi + kPi / 2;  // on the circle, heading along its tangent
  const double off = cam == 1 ? baseline / 2 : -baseline / 2;
  const double cx = R * std::cos(phi) + off * std::cos(theta), cy = R * std::sin(phi) + off * std::sin(theta);
  const double a = theta + axis(cam), ca = std::cos(a), sa = std::sin(a);
  const double f = fu(), cu = (width - 1) / 2.0;
  const size_t edges = static_cast<size_t>(width) + 1;
  edge_z_.resize(edges);
  edge_cos_.resize(edges * kWaves.size());
  for (size_t u = 0; u < edges; ++u) {
    const double xn = (static_cast<double>(u) - 0.5 - cu) / f;
    const double dx = ca + xn * sa, dy = sa - xn * ca;  // ray (u_sign -1: u to the right)
    const double dd = dx * dx + dy * dy, b = cx * dx + cy * dy, c = cx * cx + cy * cy - Rp * Rp;
    const double t = (-b - std::sqrt(b * b - dd * c)) / dd;  // nearer hit (the view lies inside the pillar)
    // The hit's direction from the pillar's axis, z = e^(i psi); each wave's
    // cos(n psi + p) = Re(z^n e^(ip)) from the powers z^(2^j): no atan2, no cos.
    const double hx = cx + t * dx, hy = cy + t * dy, inv = 1 / std::sqrt(hx * hx + hy * hy);
    std::array<Phasor, 9> pow2;
    pow2[0] = {hx * inv, hy * inv};
    for (size_t j = 1; j < pow2.size(); ++j) pow2[j] = pow2[j - 1] * pow2[j - 1];
    edge_z_[u] = pow2[0];
    for (size_t k = 0; k < kWaves.size(); ++k) {
      Phasor w = kPhasors[k];
      for (size_t j = 0; j < pow2.size(); ++j)
        if (kWaves[k].periods & (1u << j)) w = w * pow2[j];
      edge_cos_[u * kWaves.size() + k] = w.re;
    }
  }
  out.resize(static_cast<size_t>(width) * static_cast<size_t>(height));
  for (size_t u = 0; u < edges - 1; ++u) {
    const Phasor a0 = edge_z_[u], a1 = edge_z_[u + 1];
    // The pixel's arc, signed: atan of a tangent of ~2e-3 by its series (error < 1e-19).
    const double x = (a1.im * a0.re - a1.re * a0.im) / (a1.re * a0.re + a1.im * a0.im), x2 = x * x;
    const double dpsi = x * (1 - x2 * (1.0 / 3 - x2 / 5));
    // Mean of sin(n psi + p) over the pixel's arc: (cos at one end - cos at the other) / (n dpsi).
    double v = 128;
    for (size_t k = 0; k < kWaves.size(); ++k)
      v += kWaves[k].amplitude * (edge_cos_[u * kWaves.size() + k] - edge_cos_[(u + 1) * kWaves.size() + k]) /
           (kWaves[k].periods * dpsi);  // wave k's mean over the arc
    for (int r = 0; r < height; ++r) {
      const double p = gain * v + noise * noise_sample() + 0.5;  // rounded below (p > 0 here)
      out[static_cast<size_t>(r * width) + u] = static_cast<uint8_t>(p < 0 ? 0 : (p >= 255 ? 255 : static_cast<int>(p)));
    }
  }
}

void PillarScene::render(double s, double gain, std::vector<uint8_t>& cam0, std::vector<uint8_t>& cam1) {
  render_camera(0, s, gain, cam0);
  render_camera(1, s, gain, cam1);
}

}  // namespace lumavel::soak
