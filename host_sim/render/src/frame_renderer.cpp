#include "lumavel/host/render/frame_renderer.hpp"

#include <algorithm>
#include <cmath>

#include "lumavel/host/render/random.hpp"
#include "lumavel/host/render/view_renderer.hpp"

namespace lumavel::host::render {
namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr int kMaxSubframes = 256;
constexpr double kSubframeStepPx = 0.5;  // max scene motion between sub-frames (px)
// Midpoint rule over n sub-frames: a moving edge's profile errs by at most
// h^2 / (4 m) of the edge height (m = motion during the exposure, h = m / n).
constexpr double kBlurError = 0.005;
}  // namespace

double light_gain(const LightingSpec& l, double t) {
  for (const auto& d : l.dark)
    if (t >= d.first && t < d.second) return 0.0;
  if (l.flicker_amplitude == 0.0) return 1.0;
  return 1.0 + l.flicker_amplitude *
                   std::sin(2 * kPi * l.flicker_hz * t + l.flicker_phase_deg * kPi / 180);
}

FrameRenderer::FrameRenderer(const Scenario& s, const Scene& scene)
    : s_(s),
      scene_(scene),
      rig_(s.camera),
      traj_(s),
      period_ns_(static_cast<int64_t>(std::llround(1e9 / s.camera.rate_hz))) {
  for (int cam = 0; cam < 2; ++cam)
    response_[static_cast<size_t>(cam)] =
        CameraResponse(s.camera.photometric[static_cast<size_t>(cam)], s.seed, cam, s.camera.width,
                       s.camera.height, frame_time(0), s.duration_s);
}

int64_t frame_stamp_ns(const Scenario& s, int i) {
  return s.start_ns + static_cast<int64_t>(std::llround(s.camera.first_frame_s * 1e9)) +
         static_cast<int64_t>(i) * static_cast<int64_t>(std::llround(1e9 / s.camera.rate_hz));
}

int frame_count(const Scenario& s) {
  int n = 0;
  while (static_cast<double>(frame_stamp_ns(s, n) - s.start_ns) * 1e-9 < s.duration_s) ++n;
  return n;
}

int64_t FrameRenderer::frame_stamp_ns(int i) const { return render::frame_stamp_ns(s_, i); }

double FrameRenderer::frame_time(int i) const {
  return static_cast<double>(frame_stamp_ns(i) - s_.start_ns) * 1e-9;
}

int FrameRenderer::frame_count() const { return render::frame_count(s_); }

// Enough sub-frames that no visible scene point moves more than 0.5 px
// between two of them and that the blur profile errs by at most 0.5 % of an
// edge's height, that flicker is resolved, and that a lights-off edge inside
// the exposure is not missed.
int FrameRenderer::subframes(double t_mid, int cam) const {
  const double E = s_.camera.exposure_frames * static_cast<double>(period_ns_) * 1e-9;
  if (E <= 0) return 1;
  const Pinhole& pin = rig_.pinhole();
  const RigidPose mid = rig_.camera_in_world(cam, traj_.at(t_mid));
  const RigidPose a = rig_.camera_in_world(cam, traj_.at(t_mid - 0.5 * E));
  const RigidPose b = rig_.camera_in_world(cam, traj_.at(t_mid + 0.5 * E));
  double motion = 0;
  constexpr int kGrid = 7;
  for (int gy = 0; gy < kGrid; ++gy) {
    for (int gx = 0; gx < kGrid; ++gx) {
      const double u = -0.5 + pin.width * gx / (kGrid - 1.0);
      const double v = -0.5 + pin.height * gy / (kGrid - 1.0);
      Eigen::Vector3d p;
      if (!pixel_hit(scene_, pin, mid, u, v, p)) continue;
      double ua, va, ub, vb;
      if (!project(pin, a, p, ua, va) || !project(pin, b, p, ub, vb)) {
        motion = kMaxSubframes * kSubframeStepPx;
        continue;
      }
      motion = std::max(motion, std::hypot(ub - ua, vb - va));
    }
  }
  int n = static_cast<int>(std::ceil(std::max(motion / kSubframeStepPx, std::sqrt(motion / (4 * kBlurError)))));
  if (s_.lighting.flicker_amplitude > 0)
    n = std::max(n, static_cast<int>(std::ceil(8 * E * s_.lighting.flicker_hz)));
  for (const auto& d : s_.lighting.dark) {
    const bool edge_inside = (d.first > t_mid - 0.5 * E && d.first < t_mid + 0.5 * E) ||
                             (d.second > t_mid - 0.5 * E && d.second < t_mid + 0.5 * E);
    if (edge_inside) n = std::max(n, 32);
  }
  return std::clamp(n, 1, kMaxSubframes);
}

FrameStats FrameRenderer::render_radiance(int i, int cam, std::vector<double>& out) const {
  const Pinhole& pin = rig_.pinhole();
  out.assign(static_cast<size_t>(pin.width) * static_cast<size_t>(pin.height), 0.0);
  const double t_mid = frame_time(i);
  const double E = s_.camera.exposure_frames * static_cast<double>(period_ns_) * 1e-9;
  FrameStats st;
  st.subframes = subframes(t_mid, cam);
  // Midpoint rule over the exposure window centred on the timestamp.
  for (int k = 0; k < st.subframes; ++k) {
    const double t = t_mid + E * ((k + 0.5) / st.subframes - 0.5);
    const double gain = light_gain(s_.lighting, t) / st.subframes;
    const RigidPose pose = rig_.camera_in_world(cam, traj_.at(t));
    st.background_fraction += render_view(scene_, pin, pose, gain, out) / st.subframes;
  }
  return st;
}

FrameStats FrameRenderer::render(int i, int cam, std::vector<uint8_t>& out) const {
  std::vector<double> radiance;
  const FrameStats st = render_radiance(i, cam, radiance);
  response(cam).apply(frame_time(i), radiance);
  out.resize(radiance.size());
  const double sigma = s_.pixel_noise_sigma;
  Rng rng(stream_seed(s_.seed, 1, static_cast<uint64_t>(i), static_cast<uint64_t>(cam)));
  for (size_t k = 0; k < radiance.size(); ++k) {
    double v = radiance[k];
    if (sigma > 0) v += sigma * rng.gaussian();
    out[k] = static_cast<uint8_t>(std::clamp(std::nearbyint(v), 0.0, 255.0));
  }
  return st;
}

}  // namespace lumavel::host::render
