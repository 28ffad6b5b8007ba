// Pinhole stereo rig on the body frame (x forward, y left, z up). Camera
// frame: x right, y down, z optical axis. Body origin = midpoint of the two
// optical centres; cam1 is yawed by the misalignment relative to cam0.
#pragma once
#include <Eigen/Dense>
#include <memory>
#include <vector>

#include "lumavel/host/lens_distortion.hpp"
#include "lumavel/host/render/scenario.hpp"
#include "lumavel/host/render/trajectory.hpp"

namespace lumavel::host::render {

struct RigidPose {  // p_parent = R * p_child + t
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  Eigen::Vector3d t = Eigen::Vector3d::Zero();
};

// Where each sub-pixel corner of a distorted image looks in the ideal
// pinhole image: (kLensSubdiv W + 1) x (kLensSubdiv H + 1) points, row-major,
// corner (i, j) at distorted (-0.5 + i / kLensSubdiv, -0.5 + j / kLensSubdiv);
// NaN where the inverse does not settle.
constexpr int kLensSubdiv = 4;
struct LensGrid {
  int w = 0, h = 0;
  std::vector<double> u, v;
};

struct Pinhole {
  int width = 0, height = 0;
  double fu = 0, fv = 0, cu = 0, cv = 0;  // centre of pixel (0,0) is (0,0)
  LensDistortion lens;                     // none: an ideal pinhole
  // Distorted lens: the undistortion grid, computed once by StereoRig and
  // shared by all views (render_view computes it if absent).
  std::shared_ptr<const LensGrid> lens_grid;
};

Pinhole pinhole_from_fov(int width, int height, double hfov_deg, double vfov_deg);

// Pixel coordinates through the lens: ideal pinhole (u, v) <-> the distorted
// image the sensor records (ud, vd). undistort_pixel: false if the inverse
// does not settle there.
void distort_pixel(const Pinhole& p, double u, double v, double& ud, double& vd);
bool undistort_pixel(const Pinhole& p, double ud, double vd, double& u, double& v);
std::shared_ptr<const LensGrid> make_lens_grid(const Pinhole& p);

class StereoRig {
 public:
  explicit StereoRig(const CameraSpec& spec);
  const Pinhole& pinhole() const { return pin_; }
  const RigidPose& T_BS(int cam) const { return T_BS_[cam]; }
  // Camera-to-world pose for a body state.
  RigidPose camera_in_world(int cam, const BodyState& b) const;

 private:
  Pinhole pin_;
  RigidPose T_BS_[2];
};

// The body's tilt about its level (yawed) frame: Ry(pitch) * Rx(roll).
Eigen::Matrix3d body_tilt(const BodyState& b);
// Body-to-world rotation: yaw(heading) * body_tilt(b) (ZYX Euler angles;
// positive pitch turns body x (forward) towards -z, nose down).
Eigen::Matrix3d body_attitude(const BodyState& b);
RigidPose body_in_world(const BodyState& b);

}  // namespace lumavel::host::render
