// One camera image of the recording: exposure blur (average of sub-frames
// spread over the exposure, enough that the scene moves at most 0.5 px
// between two and a moving edge is within 0.5 % of its exact profile),
// lighting (flicker, lights off), each camera's photometric response,
// Gaussian pixel noise and 8-bit rounding with clipping.
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "lumavel/host/render/photometric_response.hpp"
#include "lumavel/host/render/scenario.hpp"
#include "lumavel/host/render/scene.hpp"
#include "lumavel/host/render/stereo_rig.hpp"
#include "lumavel/host/render/trajectory.hpp"

namespace lumavel::host::render {

// Multiplicative light level at scenario time t (0 while the lights are off).
double light_gain(const LightingSpec& l, double t);

struct FrameStats {
  int subframes = 0;
  double background_fraction = 0;
};

// Frame i's timestamp as written in the recording (start_ns + first_frame_s
// + i periods, the period rounded to nanoseconds), and how many frames a
// render of `s` makes (those mid-exposure before duration_s): the renderer's
// and the checks before a render's one rule.
int64_t frame_stamp_ns(const Scenario& s, int i);
int frame_count(const Scenario& s);

class FrameRenderer {
 public:
  FrameRenderer(const Scenario& s, const Scene& scene);
  int frame_count() const;
  double frame_time(int i) const;      // mid-exposure, scenario seconds
  int64_t frame_stamp_ns(int i) const;  // as written in the recording
  const StereoRig& rig() const { return rig_; }
  const Trajectory& trajectory() const { return traj_; }
  // Renders camera `cam` of frame `i` into `out` (width*height bytes).
  FrameStats render(int i, int cam, std::vector<uint8_t>& out) const;
  // The scene's radiance, before the camera's response, noise and rounding
  // (gray levels, may exceed 0..255).
  FrameStats render_radiance(int i, int cam, std::vector<double>& out) const;
  const CameraResponse& response(int cam) const { return response_[static_cast<size_t>(cam)]; }
  // How many sub-frames the exposure of camera `cam`'s frame at `t_mid` is
  // drawn with (its motion blur; reproduce weighs render times by it).
  int subframes(double t_mid, int cam) const;

 private:
  const Scenario& s_;
  const Scene& scene_;
  StereoRig rig_;
  Trajectory traj_;
  int64_t period_ns_;
  std::array<CameraResponse, 2> response_;  // fixed patterns drawn once per camera
};

}  // namespace lumavel::host::render
