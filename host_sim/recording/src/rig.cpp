#include "lumavel/host/rig.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "lumavel/host/lens_distortion.hpp"
#include "lumavel/host/recording_layout.hpp"

namespace lumavel::host {
namespace {

// Column k of the rotation part of a row-major 4x4 pose: the sensor's axis k in the body frame.
void axis(const Pose& T, int k, double out[3]) {
  for (int r = 0; r < 3; ++r) out[r] = T[static_cast<size_t>(4 * r + k)];
}

// "FILE:LINE: what" where the key's line is known, else "FILE: what".
RecordingError error_at_key(const std::string& file, long line, const std::string& what) {
  return line > 0 ? recording_error_at(file, line, what) : recording_error_in(file, what);
}

}  // namespace

CameraModel derive_camera(const CameraSensor& c, int work_width, const std::string& yaml_path) {
  double ex[3], ez[3];
  axis(c.T_BS, 0, ex);
  axis(c.T_BS, 2, ez);
  // The optical axis must look sideways, roughly in the body x-y plane.
  if (std::hypot(ez[0], ez[1]) < 0.5) {
    char axis_text[96];
    std::snprintf(axis_text, sizeof axis_text, "(%.3g, %.3g, %.3g)", ez[0], ez[1], ez[2]);
    throw error_at_key(yaml_path, c.line.T_BS, std::string("T_BS: this camera looks along body ") +
                                            (ez[2] > 0 ? "+z" : "-z") + ": its optical axis is " + axis_text +
                                            " in the body frame, more than 60 degrees out of the body x-y plane. "
                                            "lumavel needs a rig whose cameras look sideways (optical axis along "
                                            "body +y or -y), with body x forward along the travel, y left, z up, and "
                                            "the baseline along x (README, \"The rig\"). A rig with forward-looking "
                                            "cameras (such as EuRoC's, whose body z is forward) does not fit");
  }
  const double cross_z = ez[0] * ex[1] - ez[1] * ex[0];  // ((R e_z) x (R e_x)).z
  if (std::fabs(cross_z) < 0.5)
    throw error_at_key(yaml_path, c.line.T_BS,
                       "T_BS: the image u axis is not horizontal (camera rolled more than 60 degrees)");
  CameraModel m;
  const double scale = static_cast<double>(work_width) / static_cast<double>(c.width);
  m.fu = c.fu * scale;
  m.cu = (c.cu + 0.5) * scale - 0.5;  // pixel-centre convention: centre of pixel 0 is 0
  m.axis_yaw = std::atan2(ez[1], ez[0]);
  m.u_sign = cross_z > 0 ? 1 : -1;
  m.edges = undistorted_column_edges(c, work_width, m.axis_yaw, m.u_sign);
  return m;
}

namespace {

// The sensor's radial-tangential distortion applies: a coefficient is not 0.
bool lens_applies(const CameraSensor& c) {
  const std::vector<double>& d = c.distortion;
  return c.distortion_model == "radial-tangential" && std::any_of(d.begin(), d.end(), [](double k) { return k != 0; });
}

// k1, k2, p1, p2 of the sensor (missing ones 0).
LensDistortion lens_of(const CameraSensor& c) {
  LensDistortion lens;
  for (size_t i = 0; i < lens.k.size() && i < c.distortion.size(); ++i) lens.k[i] = c.distortion[i];
  return lens;
}

// How far (px) an undistorted point may miss its pixel when distorted again.
constexpr double kLensInverseTolerancePx = 0.01;

std::string g(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%g", v);
  return b;
}

}  // namespace

void check_lens_invertible(const CameraSensor& c, const std::string& yaml_path) {
  if (!lens_applies(c)) return;
  const LensDistortion lens = lens_of(c);
  const std::string coeffs = "distortion_coefficients [" + g(lens.k[0]) + ", " + g(lens.k[1]) + ", " +
                             g(lens.k[2]) + ", " + g(lens.k[3]) + "]: ";
  // Every pixel edge of the principal row (the columns' angles come from
  // there), then the top and bottom rows' edges (the whole image).
  double prev_x = -HUGE_VAL;
  for (const double v : {c.cv, -0.5, c.height - 0.5}) {
    for (int i = 0; i <= c.width; ++i) {
      const double u = i - 0.5;
      const double xd = (u - c.cu) / c.fu, yd = (v - c.cv) / c.fv;
      double x = 0, y = 0, ru = 0, rv = 0;
      lens.undistort(xd, yd, x, y);  // whether it settled: judged below, in pixels
      lens.distort(x, y, ru, rv);
      const double miss = std::hypot((ru - xd) * c.fu, (rv - yd) * c.fv);
      // Below 1e-12 in normalised coordinates the inverse is exact to
      // rounding: an absurd focal length (1e300 px, refused by the settings
      // check naming it) must not make that look like a lens fault.
      const bool exact = std::hypot(ru - xd, rv - yd) <= 1e-12;
      if (!(miss <= kLensInverseTolerancePx || exact))
        throw recording_error_in(yaml_path, coeffs + "the lens model cannot be inverted at pixel (" + g(u) + ", " +
                                                g(v) + "): no undistorted point maps to it (" +
                                                (std::isfinite(miss) ? "the nearest misses by " + g(miss) + " px"
                                                                     : std::string("the inverse diverges")) +
                                                "); is a coefficient wrong?");
      if (v == c.cv) {
        if (!(x > prev_x))
          throw recording_error_in(yaml_path, coeffs + "the undistorted columns are not in order at column edge " +
                                                  g(u) + " of the principal row: the lens folds the image");
        prev_x = x;
      }
    }
  }
}

std::vector<double> undistorted_column_edges(const CameraSensor& c, int work_width, double axis_yaw, int u_sign) {
  if (!lens_applies(c)) return {};
  const LensDistortion lens = lens_of(c);
  std::vector<double> edges(static_cast<size_t>(work_width) + 1);
  const double scale = static_cast<double>(c.width) / static_cast<double>(work_width);
  for (int u = 0; u <= work_width; ++u) {
    // Working edge u on the sensor: native pixel i spans [i - 0.5, i + 0.5].
    const double xd = (u * scale - 0.5 - c.cu) / c.fu, yd = 0;  // on the principal row
    double x = 0, y = 0;
    lens.undistort(xd, yd, x, y);  // load_recording judged the inverse (check_lens_invertible)
    edges[static_cast<size_t>(u)] = axis_yaw + u_sign * std::atan(x);
  }
  return edges;
}

double gyro_gap_s(double imu_period_s) { return std::max(EstimatorSettings{}.gyro_gap, 2.5 * imu_period_s); }

WorkingSize default_working_size(const Recording& rec) {
  return {default_columns(rec.cam[0].width), default_rows(rec.cam[0].height)};
}

EstimatorSettings derive_settings(const Recording& rec, WorkingSize size) {
  const std::string yaml0 = rec.root + "/" + layout::kCamDir[0] + "/sensor.yaml";
  if (rec.cam[0].height == 1) size.height = 1;  // line-scan sensor
  if (size.width < kMinWorkWidth || size.width > kMaxWorkWidth)
    throw RecordingError("working width " + std::to_string(size.width) + " is outside " +
                         std::to_string(kMinWorkWidth) + ".." + std::to_string(kMaxWorkWidth));
  if (size.height < 1 || size.height > kMaxWorkHeight)
    throw RecordingError("working height " + std::to_string(size.height) + " is outside 1.." +
                         std::to_string(kMaxWorkHeight));
  EstimatorSettings s;
  s.width = size.width;
  s.height = size.height;
  for (int c = 0; c < 2; ++c) {
    const CameraSensor& cam = rec.cam[c];
    const std::string yaml = rec.root + "/" + layout::kCamDir[c] + "/sensor.yaml";
    if (size.width > cam.width || size.height > cam.height)
      throw error_at_key(yaml, cam.line.resolution, "cannot bin the " + std::to_string(cam.width) + "x" +
                                         std::to_string(cam.height) + " sensor up to the working resolution " +
                                         std::to_string(size.width) + "x" + std::to_string(size.height) +
                                         " (choose a smaller --width/--height)");
    s.cam[c] = derive_camera(cam, size.width, yaml);
  }
  // Baseline: x of the vector from cam0's optical centre to cam1's (body frame).
  s.baseline = rec.cam[1].T_BS[3] - rec.cam[0].T_BS[3];
  if (std::fabs(s.baseline) < 1e-4)
    throw error_at_key(yaml0, rec.cam[0].line.T_BS,
                       "T_BS: cam0 and cam1 are less than 0.1 mm apart along body x (no baseline)");
  s.frame_period = rec.frame_period_s;
  s.gyro_gap = gyro_gap_s(rec.imu_period_s);
  const double hfov = 2.0 * std::atan(0.5 * rec.cam[0].width / rec.cam[0].fu);
  s.kernels = default_kernels(hfov);
  return s;
}

}  // namespace lumavel::host
