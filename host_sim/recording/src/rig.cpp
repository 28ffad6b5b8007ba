#include "lumavel/host/rig.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "lumavel/host/lens_distortion.hpp"
#include "lumavel/host/recording_layout.hpp"
#include "lumavel/units/config_fields.hpp"

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

// ((R e_z) x (R e_x)).z: the image u axis against the body's yaw.
double u_cross_z(const Pose& T) {
  double ex[3], ez[3];
  axis(T, 0, ex);
  axis(T, 2, ez);
  return ez[0] * ex[1] - ez[1] * ex[0];
}

}  // namespace

int u_sign_of(const CameraSensor& c) { return u_cross_z(c.T_BS) > 0 ? 1 : -1; }

CameraModel derive_camera(const CameraSensor& c, int work_width, const std::string& yaml_path) {
  double ez[3];
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
  const double cross_z = u_cross_z(c.T_BS);
  if (std::fabs(cross_z) < 0.5)
    throw error_at_key(yaml_path, c.line.T_BS,
                       "T_BS: the image u axis is not horizontal (camera rolled more than 60 degrees)");
  CameraModel m;
  const double scale = static_cast<double>(work_width) / static_cast<double>(c.width);
  m.fu = c.fu * scale;
  m.cu = (c.cu + 0.5) * scale - 0.5;  // pixel-centre convention: centre of pixel 0 is 0
  m.axis_yaw = std::atan2(ez[1], ez[0]);
  m.u_sign = u_sign_of(c);
  m.edges = undistorted_column_edges(c, work_width, m.axis_yaw, m.u_sign);
  m.elevation_scale = lens_elevation_scales(c, work_width);
  return m;
}

double horizontal_fov(const CameraSensor& c) { return 2.0 * std::atan(0.5 * c.width / c.fu); }

bool lens_applies(const CameraSensor& c) {
  const std::vector<double>& d = c.distortion;
  return c.distortion_model == "radial-tangential" && std::any_of(d.begin(), d.end(), [](double k) { return k != 0; });
}

LensDistortion lens_of(const CameraSensor& c) {
  LensDistortion lens;
  for (size_t i = 0; i < lens.k.size() && i < c.distortion.size(); ++i) lens.k[i] = c.distortion[i];
  return lens;
}

namespace {

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
  // At the coefficients' line where they were read from a file.
  auto refused = [&](const std::string& what) {
    return c.line.distortion > 0 ? recording_error_at(yaml_path, c.line.distortion, coeffs + what)
                                 : recording_error_in(yaml_path, coeffs + what);
  };
  // Every pixel edge of the principal row (its order is checked), then the
  // top and bottom rows' edges (the whole image, over which the columns'
  // angles and elevation scales are taken).
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
        throw refused("the lens model cannot be inverted at pixel (" + g(u) + ", " + g(v) +
                      "): no undistorted point maps to it (" +
                      (std::isfinite(miss) ? "the nearest misses by " + g(miss) + " px"
                                           : std::string("the inverse diverges")) +
                      "); is a coefficient wrong?");
      if (!lens.one_to_one_at(x, y))
        throw refused("the lens model cannot be inverted one-to-one at pixel (" + g(u) + ", " + g(v) +
                      "): it folds the image over there; is a coefficient wrong?");
      const double scale = lens_radial_scale(xd, yd, x, y);
      if (!plausible_lens_scale(scale))
        throw refused("the lens model cannot be inverted plausibly at pixel (" + g(u) + ", " + g(v) +
                      "): it moves the pixel to " + g(scale) + " times its pinhole distance from the centre (a lens "
                      "moves it to between " + g(kLensMinRadialScale) + " and " + g(kLensMaxRadialScale) +
                      " times); is a coefficient wrong?");
      if (v == c.cv) {
        if (!(x > prev_x))
          throw refused("the undistorted columns are not in order at column edge " + g(u) +
                        " of the principal row: the lens folds the image");
        prev_x = x;
      }
    }
  }
}

namespace {

// A distorted column is not a meridian: its rows look at different yaws and
// at elevations a pinhole's would not. Both are taken over the elevation band
// that every column sees (the band the firmware sums, kernel_bank.hpp),
// |tan E| <= T, on the sensor's native pixels.
class LensColumns {
 public:
  LensColumns(const CameraSensor& c, int work_width)
      : c_(c), lens_(lens_of(c)), scale_(static_cast<double>(c.width) / static_cast<double>(work_width)) {
    // T: the least |tan E| a column reaches at the image's top or bottom edge.
    for (int e = 0; e <= 2 * work_width; ++e) {  // every working edge and centre
      const double u = e * scale_ / 2 - 0.5;
      tan_band_ = std::min({tan_band_, -tan_e(u, -0.5), tan_e(u, c.height - 0.5)});
    }
  }
  // Mean yaw from the axis (rad, image u positive) of native column position u's points in the band.
  double mean_yaw(double u) const {
    constexpr int kSamples = 64;
    const double top = row_at(u, -tan_band_), bottom = row_at(u, tan_band_);
    double sum = 0;
    for (int j = 0; j < kSamples; ++j) sum += yaw(u, top + (j + 0.5) * (bottom - top) / kSamples);
    return sum / kSamples;
  }
  // f d(tan E)/d(row) averaged over the band: the band's span over its rows.
  double elevation_scale(double u) const {
    return 2 * tan_band_ * c_.fv / (row_at(u, tan_band_) - row_at(u, -tan_band_));
  }
  double working_edge(int u) const { return u * scale_ - 0.5; }
  double working_centre(int u) const { return (u + 0.5) * scale_ - 0.5; }

 private:
  void undistort(double u, double v, double& x, double& y) const {
    lens_.undistort((u - c_.cu) / c_.fu, (v - c_.cv) / c_.fv, x, y);  // judged by check_lens_invertible
  }
  double tan_e(double u, double v) const {
    double x = 0, y = 0;
    undistort(u, v, x, y);
    return y / std::sqrt(1 + x * x);
  }
  double yaw(double u, double v) const {
    double x = 0, y = 0;
    undistort(u, v, x, y);
    return std::atan(x);
  }
  // The row (native, fractional) where column position u sees tan E = t: by
  // bisection, tan E rising down the column (the lens does not fold it).
  double row_at(double u, double t) const {
    double lo = -0.5, hi = c_.height - 0.5;
    for (int i = 0; i < 50; ++i) {
      const double mid = (lo + hi) / 2;
      (tan_e(u, mid) < t ? lo : hi) = mid;
    }
    return (lo + hi) / 2;
  }

  const CameraSensor& c_;
  LensDistortion lens_;
  double scale_;
  double tan_band_ = HUGE_VAL;
};

}  // namespace

std::vector<double> undistorted_column_edges(const CameraSensor& c, int work_width, double axis_yaw, int u_sign) {
  if (!lens_applies(c)) return {};
  const LensColumns lc(c, work_width);
  std::vector<double> edges(static_cast<size_t>(work_width) + 1);
  for (int u = 0; u <= work_width; ++u) edges[static_cast<size_t>(u)] = axis_yaw + u_sign * lc.mean_yaw(lc.working_edge(u));
  return edges;
}

std::vector<double> lens_elevation_scales(const CameraSensor& c, int work_width) {
  if (!lens_applies(c)) return {};
  const LensColumns lc(c, work_width);
  std::vector<double> scales(static_cast<size_t>(work_width));
  for (int u = 0; u < work_width; ++u) scales[static_cast<size_t>(u)] = lc.elevation_scale(lc.working_centre(u));
  return scales;
}

namespace {

// Whether the settings' kernels reach past a camera's view (the core's rule,
// through to_fixed_config).
bool kernels_outside_view(const EstimatorSettings& s) {
  try {
    (void)to_fixed_config(s);
  } catch (const SettingsError& e) {
    return e.setting() == "kernels";
  }
  return false;
}

// The smaller angle (rad) from a camera's optical axis to its image's left or
// right edge, of the two cameras (pinhole: the outer edges of the edge pixels).
double narrower_half_view(const CameraSensor& a, const CameraSensor& b) {
  double least = HUGE_VAL;
  for (const CameraSensor* c : {&a, &b})
    least = std::min({least, std::atan((c->cu + 0.5) / c->fu), std::atan((c->width - 0.5 - c->cu) / c->fu)});
  return least;
}

}  // namespace

double gyro_gap_s(double imu_period_s) { return std::max(EstimatorSettings{}.gyro_gap, kGapPeriods * imu_period_s); }

double focal_length_mismatch(const Recording& rec) {
  const CameraSensor &a = rec.cam[0], &b = rec.cam[1];
  return std::max(std::fabs(b.fu / a.fu - 1), std::fabs(b.fv / a.fv - 1));
}

double max_gap_s(double frame_period_s) {
  return std::min(config::spec(config::Quantity::kMaxGap).hi,
                  std::max(EstimatorSettings{}.max_gap, kGapPeriods * frame_period_s));
}

WorkingSize default_working_size(const Recording& rec) {
  return {default_columns(rec.cam[0].width), default_rows(rec.cam[0].height)};
}

void check_bins_down(const Recording& rec, WorkingSize size, const std::string& asked_by) {
  for (int c = 0; c < 2; ++c) {
    const CameraSensor& cam = rec.cam[c];
    if (size.width > cam.width || size.height > cam.height)
      throw error_at_key(rec.root + "/" + layout::kCamDir[c] + "/sensor.yaml", cam.line.resolution,
                         "cannot bin the " + std::to_string(cam.width) + "x" + std::to_string(cam.height) +
                             " sensor up to the working resolution " + std::to_string(size.width) + "x" +
                             std::to_string(size.height) + " (choose a smaller " + asked_by + ")");
  }
}

EstimatorSettings derive_settings(const Recording& rec, WorkingSize size) {
  const std::string yaml0 = rec.root + "/" + layout::kCamDir[0] + "/sensor.yaml";
  if (rec.cam[0].height == 1) size.height = 1;  // line-scan sensor
  for (int c = 0; c < 2; ++c)
    if (rec.cam[c].width < kMinWorkWidth)
      throw error_at_key(rec.root + "/" + layout::kCamDir[c] + "/sensor.yaml", rec.cam[c].line.resolution,
                         "resolution: the sensor is " + std::to_string(rec.cam[c].width) +
                             " columns wide; lumavel works at " + std::to_string(kMinWorkWidth) +
                             " columns or more (the kernels need them)");
  if (size.width < kMinWorkWidth || size.width > kMaxWorkWidth)
    throw RecordingError("working width " + std::to_string(size.width) + " is outside " +
                         std::to_string(kMinWorkWidth) + ".." + std::to_string(kMaxWorkWidth));
  if (size.height < 1 || size.height > kMaxWorkHeight)
    throw RecordingError("working height " + std::to_string(size.height) + " is outside 1.." +
                         std::to_string(kMaxWorkHeight));
  EstimatorSettings s;
  s.width = size.width;
  s.height = size.height;
  check_bins_down(rec, size);
  for (int c = 0; c < 2; ++c)
    s.cam[c] = derive_camera(rec.cam[c], size.width, rec.root + "/" + layout::kCamDir[c] + "/sensor.yaml");
  // Baseline: x of the vector from cam0's optical centre to cam1's (body frame).
  s.baseline = rec.cam[1].T_BS[3] - rec.cam[0].T_BS[3];
  if (std::fabs(s.baseline) < 1e-4)
    throw error_at_key(yaml0, rec.cam[0].line.T_BS,
                       "T_BS: cam0 and cam1 are less than 0.1 mm apart along body x (no baseline)");
  // The baseline runs along the travel: cameras side by side across it (or
  // stacked) with a millimetre of x between them would be read as a
  // millimetre baseline, and every speed scaled by it.
  const double across = std::hypot(rec.cam[1].T_BS[7] - rec.cam[0].T_BS[7], rec.cam[1].T_BS[11] - rec.cam[0].T_BS[11]);
  if (across > std::fabs(s.baseline)) {
    char v[160];
    std::snprintf(v, sizeof v, "(%.4g, %.4g, %.4g) m", s.baseline, rec.cam[1].T_BS[7] - rec.cam[0].T_BS[7],
                  rec.cam[1].T_BS[11] - rec.cam[0].T_BS[11]);
    throw error_at_key(yaml0, rec.cam[0].line.T_BS,
                       std::string("T_BS: cam1's optical centre minus cam0's is ") + v +
                           " in the body frame: more across body x than along it; the baseline must lie along body x "
                           "(the direction of travel), within 45 degrees");
  }
  s.frame_period = rec.frame_period_s;
  s.gyro_gap = gyro_gap_s(rec.imu_period_s);
  s.max_gap = max_gap_s(rec.frame_period_s);
  const double hfov = horizontal_fov(rec.cam[0]);
  s.kernels = default_kernels(hfov);
  // An off-centre principal point (a sensor read out through a window off its
  // centre): the kernels, centred on the optical axis and sized to the whole
  // view, can reach past the image's nearer edge. Only then are they sized to
  // twice the narrower side's reach (was: refused, "a kernel's +-2.5 sigma
  // core falls outside a camera's view", blaming the field of view). A
  // camera whose principal point is near the centre keeps the kernels above.
  // Only for cameras of one focal length (twin sensors, one read out off
  // centre) and an optical axis inside both images: cameras whose views
  // differ, or an axis outside an image (reach <= 0), are refused naming the
  // camera that cannot hold the kernels and its view.
  if (kernels_outside_view(s) && focal_length_mismatch(rec) < kFocalMismatchWarn) {
    const double reach = narrower_half_view(rec.cam[0], rec.cam[1]);
    if (reach > 0) s.kernels = default_kernels(2 * reach);
  }
  s.elevation_band = config::elevation_band_for(hfov);
  return s;
}

}  // namespace lumavel::host
