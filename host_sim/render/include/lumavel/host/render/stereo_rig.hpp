// Pinhole stereo rig on the body frame (x forward, y left, z up). Camera
// frame: x right, y down, z optical axis. Body origin = midpoint of the two
// optical centres; cam1 is yawed by the misalignment relative to cam0.
#pragma once
#include <Eigen/Dense>

#include "lumavel/host/render/scenario.hpp"
#include "lumavel/host/render/trajectory.hpp"

namespace lumavel::host::render {

struct RigidPose {  // p_parent = R * p_child + t
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  Eigen::Vector3d t = Eigen::Vector3d::Zero();
};

struct Pinhole {
  int width = 0, height = 0;
  double fu = 0, fv = 0, cu = 0, cv = 0;  // centre of pixel (0,0) is (0,0)
};

Pinhole pinhole_from_fov(int width, int height, double hfov_deg, double vfov_deg);

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

RigidPose body_in_world(const BodyState& b);

}  // namespace lumavel::host::render
