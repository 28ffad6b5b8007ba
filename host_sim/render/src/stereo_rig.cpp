#include "lumavel/host/render/stereo_rig.hpp"

#include <cmath>

namespace lumavel::host::render {
namespace {
constexpr double kPi = 3.14159265358979323846;
Eigen::Matrix3d yaw(double a) { return Eigen::AngleAxisd(a, Eigen::Vector3d::UnitZ()).toRotationMatrix(); }
}  // namespace

Pinhole pinhole_from_fov(int width, int height, double hfov_deg, double vfov_deg) {
  Pinhole p;
  p.width = width;
  p.height = height;
  // The image spans [-0.5, W-0.5]: its half-width W/2 subtends hfov/2.
  p.fu = 0.5 * width / std::tan(0.5 * hfov_deg * kPi / 180.0);
  p.fv = 0.5 * height / std::tan(0.5 * vfov_deg * kPi / 180.0);
  p.cu = 0.5 * (width - 1);
  p.cv = 0.5 * (height - 1);
  return p;
}

void distort_pixel(const Pinhole& p, double u, double v, double& ud, double& vd) {
  double xd, yd;
  p.lens.distort((u - p.cu) / p.fu, (v - p.cv) / p.fv, xd, yd);
  ud = p.cu + p.fu * xd;
  vd = p.cv + p.fv * yd;
}

bool undistort_pixel(const Pinhole& p, double ud, double vd, double& u, double& v) {
  double x, y;
  const bool ok = p.lens.undistort((ud - p.cu) / p.fu, (vd - p.cv) / p.fv, x, y);
  u = p.cu + p.fu * x;
  v = p.cv + p.fv * y;
  return ok;
}

std::shared_ptr<const LensGrid> make_lens_grid(const Pinhole& p) {
  auto g = std::make_shared<LensGrid>();
  g->w = kLensSubdiv * p.width + 1;
  g->h = kLensSubdiv * p.height + 1;
  g->u.resize(static_cast<size_t>(g->w) * static_cast<size_t>(g->h));
  g->v.resize(g->u.size());
  for (int j = 0; j < g->h; ++j) {
    for (int i = 0; i < g->w; ++i) {
      const size_t k = static_cast<size_t>(j) * static_cast<size_t>(g->w) + static_cast<size_t>(i);
      double u, v;
      if (!undistort_pixel(p, -0.5 + static_cast<double>(i) / kLensSubdiv,
                           -0.5 + static_cast<double>(j) / kLensSubdiv, u, v))
        u = v = std::nan("");
      g->u[k] = u;
      g->v[k] = v;
    }
  }
  return g;
}

StereoRig::StereoRig(const CameraSpec& spec)
    : pin_(pinhole_from_fov(spec.width, spec.height, spec.hfov_deg, spec.vfov_deg)) {
  pin_.lens.k = spec.distortion;
  if (!pin_.lens.none()) pin_.lens_grid = make_lens_grid(pin_);
  // Columns = camera axes in the body frame. Looking left: optical axis +y,
  // image down = -z, image right = y_c x z_c = +x (forward).
  Eigen::Matrix3d look;
  if (spec.look == LookSide::Left) {
    look << 1, 0, 0,  //
        0, 0, 1,      //
        0, -1, 0;
  } else {
    look << -1, 0, 0,  //
        0, 0, -1,      //
        0, -1, 0;
  }
  const Eigen::Matrix3d R0 = yaw(spec.rig_yaw_deg * kPi / 180.0) * look;
  const Eigen::Matrix3d R1 = yaw(spec.misalignment_deg * kPi / 180.0) * R0;
  const double half = 0.5 * spec.baseline_m * (spec.cam1_ahead ? 1.0 : -1.0);
  T_BS_[0].R = R0;
  T_BS_[0].t = Eigen::Vector3d(-half, 0, 0);
  T_BS_[1].R = R1;
  T_BS_[1].t = Eigen::Vector3d(half, 0, 0);
}

Eigen::Matrix3d body_tilt(const BodyState& b) {
  return Eigen::AngleAxisd(b.pitch, Eigen::Vector3d::UnitY()).toRotationMatrix() *
         Eigen::AngleAxisd(b.roll, Eigen::Vector3d::UnitX()).toRotationMatrix();
}

Eigen::Matrix3d body_attitude(const BodyState& b) {
  // Level (no vibration): the yaw alone, bit for bit as before tilts existed.
  if (b.pitch == 0.0 && b.roll == 0.0) return yaw(b.heading);
  return yaw(b.heading) * body_tilt(b);
}

RigidPose body_in_world(const BodyState& b) {
  RigidPose p;
  p.R = body_attitude(b);
  p.t = Eigen::Vector3d(b.x, b.y, b.z);
  return p;
}

RigidPose StereoRig::camera_in_world(int cam, const BodyState& b) const {
  const RigidPose wb = body_in_world(b);
  RigidPose out;
  out.R = wb.R * T_BS_[cam].R;
  out.t = wb.R * T_BS_[cam].t + wb.t;
  return out;
}

}  // namespace lumavel::host::render
