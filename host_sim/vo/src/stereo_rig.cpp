#include "lumavel/host/vo/stereo_rig.hpp"

#include <cmath>
#include <cstdio>

#include "lumavel/host/recording_layout.hpp"
#include "lumavel/host/rig.hpp"

namespace lumavel::host::vo {
namespace {

constexpr double kDegPerRad = 57.29577951308232;

std::string yaml_of(const Recording& rec, int c) { return rec.root + "/" + layout::kCamDir[c] + "/sensor.yaml"; }

std::string fmt(const char* f, double a, double b = 0) {
  char buf[160];
  std::snprintf(buf, sizeof buf, f, a, b);
  return buf;
}

VoCamera camera_at(const CameraSensor& s, int width, int height, bool ignore_distortion, const std::string& yaml) {
  VoCamera c;
  const double sx = static_cast<double>(width) / s.width, sy = static_cast<double>(height) / s.height;
  // Binning by area keeps the pixel-centre convention: a native coordinate
  // x (centre of pixel 0 = 0) is (x + 0.5) * scale - 0.5 on the working grid.
  c.K = cv::Matx33d(s.fu * sx, 0, (s.cu + 0.5) * sx - 0.5, 0, s.fv * sy, (s.cv + 0.5) * sy - 0.5, 0, 0, 1);
  for (int i = 0; i < 4; ++i)
    c.distortion[i] = ignore_distortion || static_cast<size_t>(i) >= s.distortion.size() ? 0.0
                                                                                       : s.distortion[static_cast<size_t>(i)];
  for (int r = 0; r < 3; ++r) {
    for (int k = 0; k < 3; ++k) c.R_BC(r, k) = s.T_BS[static_cast<size_t>(4 * r + k)];
    c.c_B[r] = s.T_BS[static_cast<size_t>(4 * r + 3)];
  }
  const cv::Matx33d should_be_identity = c.R_BC.t() * c.R_BC;
  double off = 0;
  for (int r = 0; r < 3; ++r)
    for (int k = 0; k < 3; ++k) off = std::fmax(off, std::fabs(should_be_identity(r, k) - (r == k ? 1.0 : 0.0)));
  if (off > 1e-3 || cv::determinant(c.R_BC) <= 0)
    throw recording_error_in(yaml, "T_BS: the rotation part is not a rotation (R^T R differs from I by " +
                                       fmt("%.2g", off) + " or det <= 0): the VO needs the camera's true pose");
  c.hfov = horizontal_fov(s);
  return c;
}

}  // namespace

StereoRig make_stereo_rig(const Recording& rec, int width, int height, bool ignore_distortion) {
  StereoRig rig;
  rig.width = width;
  rig.height = height;
  for (int i = 0; i < 2; ++i) {
    const CameraSensor& s = rec.cam[i];
    const std::string yaml = yaml_of(rec, i);
    if (s.height < kMinVoHeight)
      throw recording_error_in(yaml, "resolution [" + std::to_string(s.width) + ", " + std::to_string(s.height) +
                                         "]: the VO needs 2-D images of at least " + std::to_string(kMinVoWidth) +
                                         "x" + std::to_string(kMinVoHeight) + " (a line-scan sensor cannot be tracked)");
    if (width < kMinVoWidth || height < kMinVoHeight)
      throw recording_error_in(yaml, "working size " + std::to_string(width) + "x" + std::to_string(height) +
                                         " is below the VO's minimum " + std::to_string(kMinVoWidth) + "x" +
                                         std::to_string(kMinVoHeight));
    if (width > s.width || height > s.height)
      throw recording_error_in(yaml, "cannot bin the " + std::to_string(s.width) + "x" + std::to_string(s.height) +
                                         " sensor up to the working size " + std::to_string(width) + "x" +
                                         std::to_string(height));
    rig.cam[i] = camera_at(s, width, height, ignore_distortion, yaml);
  }
  const VoCamera &c0 = rig.cam[0], &c1 = rig.cam[1];
  rig.R_10 = c1.R_BC.t() * c0.R_BC;
  rig.t_10 = c1.R_BC.t() * (c0.c_B - c1.c_B);
  rig.baseline = cv::norm(c1.c_B - c0.c_B);
  if (rig.baseline < 1e-3)
    throw recording_error_in(yaml_of(rec, 1), "T_BS: cam1 is " + fmt("%.2g m", rig.baseline) +
                                                  " from cam0: stereo needs a baseline of at least 1 mm");
  // Optical axes (camera z) in the body frame: the views must share most of
  // their field for stereo matching.
  const cv::Vec3d z0(c0.R_BC(0, 2), c0.R_BC(1, 2), c0.R_BC(2, 2)), z1(c1.R_BC(0, 2), c1.R_BC(1, 2), c1.R_BC(2, 2));
  const double angle = std::acos(std::fmax(-1.0, std::fmin(1.0, z0.dot(z1))));
  const double limit = 0.5 * std::fmin(c0.hfov, c1.hfov);
  if (angle > limit)
    throw recording_error_in(yaml_of(rec, 1), "T_BS: the optical axes of cam0 and cam1 are " +
                                                  fmt("%.1f deg apart: the views overlap too little for stereo "
                                                      "(the VO needs at most half the field of view, %.1f deg)",
                                                      angle * kDegPerRad, limit * kDegPerRad));
  rig.frame_period = rec.frame_period_s;
  return rig;
}

}  // namespace lumavel::host::vo
