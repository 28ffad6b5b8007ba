// A small synthetic stereo rig for the core tests: two upright pinhole
// cameras looking left (body +y) at a textured wall, cam1 ahead of cam0 by h,
// each pixel the mean of an S x S grid of rays (area averaging).
#pragma once
#include <cmath>
#include <cstdint>
#include <functional>
#include <vector>

#include "left_rig.hpp"
#include "lumavel/host/settings.hpp"

namespace lumavel::test {

struct Pose2 {
  double x = 0, y = 0, theta = 0;  // body origin in the world, yaw (CCW)
};

struct SyntheticRig {
  int width = 40, height = 30;
  double hfov = 50.0 * M_PI / 180, vfov = 40.0 * M_PI / 180;
  double baseline = 0.08;       // cam1 ahead of cam0 along body x
  double misalignment = 0;      // yaw of cam1 relative to cam0, rad
  double wall = 2.0;            // wall at world y = wall
  int supersample = 3;
  // Wall brightness (0..255) at wall coordinates (X along the wall, Z up).
  std::function<double(double, double)> texture = [](double X, double Z) {
    return 128 + 45 * std::sin(2 * M_PI * X / 0.37) * std::cos(2 * M_PI * Z / 0.9) +
           30 * std::sin(2 * M_PI * X / 0.23 + 1.3) + 20 * std::sin(2 * M_PI * X / 0.71 + 0.4);
  };
  double noise = 0;    // additive Gaussian, gray levels (deterministic LCG)
  double gain = 1;     // global lighting gain
  // Each camera's photometric response: y = cam_gain (1 + vignetting r^2) x
  // + black + column pattern (Gaussian, sigma column_offset gray levels, drawn
  // once per camera from its own seed); r = 1 at the image corner.
  double cam_gain[2] = {1, 1}, cam_black[2] = {0, 0}, vignetting[2] = {0, 0};
  double column_offset = 0;
  uint64_t seed = 1;
  // A radial lens on both cameras (k1 < 0: barrel): pixel coordinates are
  // the distorted ones, x_d = x (1 + k1 r^2 + k2 r^4) of the ray's pinhole x.
  double k1 = 0, k2 = 0;

  double fu() const { return left_rig_fu(width, hfov); }
  double fv() const { return height / 2.0 / std::tan(vfov / 2); }
  double axis(int cam) const { return left_rig_axis(cam, misalignment); }

  host::EstimatorSettings settings() const { return left_rig_settings(width, height, hfov, baseline, misalignment); }

  // Renders camera `cam` of a body at `pose`.
  std::vector<uint8_t> render(int cam, const Pose2& pose) {
    std::vector<uint8_t> img(static_cast<size_t>(width * height));
    const double off = cam == 1 ? baseline / 2 : -baseline / 2;
    const double cx = pose.x + off * std::cos(pose.theta), cy = pose.y + off * std::sin(pose.theta);
    const double a = pose.theta + axis(cam);
    const double fx = fu(), fy = fv(), cu = (width - 1) / 2.0, cv = (height - 1) / 2.0;
    const int S = supersample;
    for (int v = 0; v < height; ++v)
      for (int u = 0; u < width; ++u) {
        double acc = 0;
        for (int i = 0; i < S; ++i)
          for (int j = 0; j < S; ++j) {
            double xn = (u + (i + 0.5) / S - 0.5 - cu) / fx;
            double yn = (v + (j + 0.5) / S - 0.5 - cv) / fy;
            undistort(xn, yn);
            const double dx = xn * std::sin(a) + std::cos(a), dy = -xn * std::cos(a) + std::sin(a);
            const double t = (wall - cy) / dy;
            acc += texture(cx + t * dx, -t * yn);
          }
        const double du = (u - cu) / (width / 2.0), dv = (v - cv) / (height / 2.0);
        const double r2 = (du * du + dv * dv) / 2;
        double p = cam_gain[cam] * (1 + vignetting[cam] * r2) * gain * acc / (S * S) + cam_black[cam] +
                   column_pattern(cam, u) + noise * gaussian();
        p = std::fmin(255, std::fmax(0, std::round(p)));
        img[static_cast<size_t>(v * width + u)] = static_cast<uint8_t>(p);
      }
    return img;
  }

  // The lens's inverse by fixed-point iteration (monotonic lenses settle).
  void undistort(double& x, double& y) const {
    if (k1 == 0 && k2 == 0) return;
    const double xd = x, yd = y;
    for (int i = 0; i < 60; ++i) {
      const double r2 = x * x + y * y, f = 1 + k1 * r2 + k2 * r2 * r2;
      x = xd / f;
      y = yd / f;
    }
  }

  // The column's fixed offset: the same in every frame.
  double column_pattern(int cam, int u) const {
    if (column_offset == 0) return 0;
    uint64_t z = (static_cast<uint64_t>(cam) << 32 | static_cast<uint64_t>(u)) * uint64_t{0x9E3779B97F4A7C15u} + 12345u;
    z = (z ^ (z >> 30)) * uint64_t{0xBF58476D1CE4E5B9u};
    z = (z ^ (z >> 27)) * uint64_t{0x94D049BB133111EBu};
    z ^= z >> 31;
    const double uni = (static_cast<double>(z >> 11) + 0.5) / 9007199254740992.0;  // (0, 1)
    return column_offset * std::sqrt(3.0) * (2 * uni - 1);  // uniform with that sigma
  }
  double gaussian() {
    // Box-Muller on a 64-bit LCG: deterministic across platforms.
    auto uni = [this] {
      seed = seed * 6364136223846793005ull + 1442695040888963407ull;
      return (static_cast<double>(seed >> 11) + 0.5) / 9007199254740992.0;
    };
    const double u1 = uni(), u2 = uni();
    return std::sqrt(-2 * std::log(u1)) * std::cos(2 * M_PI * u2);
  }
};

}  // namespace lumavel::test
