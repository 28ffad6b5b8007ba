// A cheap synthetic world for the day-long soak: the rig drives on a circle
// of radius R around a textured pillar (radius R - D) and both cameras look
// left, at the pillar, D away. Driving around it turns the rig for ever (the
// heading wraps), reversing turns it back, the scene distance stays D.
// Each pixel is the exact mean of the texture (sinusoids with a whole number
// of periods around the pillar) over the arc between the pixel's edge rays,
// so a frame costs (width + 1) ray hits per camera, not a renderer.
#pragma once
#include <cstdint>
#include <vector>

#include "lumavel/host/settings.hpp"

namespace lumavel::soak {

// A unit complex number e^(i a): plain doubles, so that products stay a few multiplications.
struct Phasor {
  double re, im;
  Phasor operator*(const Phasor& o) const { return {re * o.re - im * o.im, re * o.im + im * o.re}; }
};

struct PillarScene {
  int width = 40, height = 4;
  double hfov = 50.0 * 3.14159265358979323846 / 180;
  double baseline = 0.08;     // cam1 ahead of cam0 along body x, m
  double misalignment = 0.017;  // yaw of cam1 relative to cam0, rad (1 deg)
  double path_radius = 20;    // R, m
  double distance = 2;        // D, m: camera to pillar
  double noise = 1.0;         // gray levels, per pixel, independent
  uint64_t seed = 11;

  // Settings of both engines for this rig (default configuration otherwise).
  host::EstimatorSettings settings() const;
  // Both cameras at arc position s (m, CCW positive) under lighting gain
  // `gain`: width * height bytes each, every row the column's value plus its own noise.
  void render(double s, double gain, std::vector<uint8_t>& cam0, std::vector<uint8_t>& cam1);

 private:
  double fu() const;
  double axis(int cam) const;
  void render_camera(int cam, double s, double gain, std::vector<uint8_t>& out);
  double noise_sample();
  std::vector<Phasor> edge_z_;   // scratch, per edge: the hit's direction e^(i psi) ...
  std::vector<double> edge_cos_;  // ... and each wave's cos(n psi + p)
};

}  // namespace lumavel::soak
