// Renders one instantaneous view of the scene: each pixel is the area average
// of the scene over the pixel (exact box filter on each plane through the
// patterns' rectangle integrals; pixels whose footprint is not close to a
// rectangle, or that straddle a plane's horizon, are split up to 4x4).
// With a distorted lens (Pinhole::lens) the pixels are those of the
// distorted image: pixel coordinates in and out of these functions are
// distorted ones.
#pragma once
#include <vector>

#include "lumavel/host/render/scene.hpp"
#include "lumavel/host/render/stereo_rig.hpp"

namespace lumavel::host::render {

// Planes a scenario may have (a street with parked cars of several planes
// each needs over 100); the renderer keeps per-pixel candidate lists of
// this size on the stack (sample_rect: 64 bytes per plane and level).
constexpr int kMaxScenePlanes = 256;

// Adds gain * radiance to `accum` (width*height, row-major). Returns the
// fraction of the image that shows the background.
double render_view(const Scene& scene, const Pinhole& cam, const RigidPose& T_WC, double gain,
                   std::vector<double>& accum);

// World point seen by pixel (u, v) on the nearest plane; false if background.
bool pixel_hit(const Scene& scene, const Pinhole& cam, const RigidPose& T_WC, double u, double v,
               Eigen::Vector3d& hit);

// Pixel coordinates of a world point; false if behind the camera.
bool project(const Pinhole& cam, const RigidPose& T_WC, const Eigen::Vector3d& p_w, double& u,
             double& v);

}  // namespace lumavel::host::render
