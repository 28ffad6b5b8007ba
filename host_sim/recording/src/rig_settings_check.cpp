#include "lumavel/host/rig_settings_check.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "lumavel/host/csv_table.hpp"
#include "lumavel/host/path_check.hpp"
#include "lumavel/host/recording_error.hpp"
#include "lumavel/host/recording_layout.hpp"
#include "lumavel/host/rig.hpp"
#include "lumavel/host/sensor_yaml.hpp"
#include "lumavel/units/config_fields.hpp"

namespace lumavel::host {
namespace {

// "FILE:LINE" of a key, or "FILE" when the recording was not read from files
// (through shown_path, as recording_error_at shows a file).
std::string file_at(const std::string& file, long line) {
  return line > 0 ? shown_path(file) + ":" + std::to_string(line) : shown_path(file);
}

}  // namespace

std::string setting_source(const Recording& rec, const std::string& setting) {
  const std::string cam[2] = {rec.root + "/" + layout::kCamDir[0] + "/sensor.yaml",
                              rec.root + "/" + layout::kCamDir[1] + "/sensor.yaml"};
  for (int i = 0; i < 2; ++i) {
    const std::string c = "cam[" + std::to_string(i) + "].";
    if (setting == c + "fu" || setting == c + "cu")
      return file_at(cam[i], rec.cam[i].line.intrinsics) + ": intrinsics (at the working resolution)";
    if (setting == c + "axis_yaw") return file_at(cam[i], rec.cam[i].line.T_BS) + ": T_BS";
  }
  if (setting == "baseline")
    return file_at(cam[0], rec.cam[0].line.T_BS) + " and " + file_at(std::string(layout::kCamDir[1]) + "/sensor.yaml",
                                                           rec.cam[1].line.T_BS) +
           ": T_BS (the baseline is cam1's x minus cam0's)";
  // With one frame or one gyro sample the period is 1 / rate_hz (load_recording).
  if (setting == "frame_period")
    return rec.frames.size() < 2
               ? file_at(cam[0], rec.cam[0].line.rate_hz) + ": rate_hz (one frame: the frame period is 1 / rate_hz)"
               : shown_path(rec.root + "/" + layout::kCamDir[0] + "/data.csv") + ": the median interval between frames";
  if (setting == "gyro_gap")
    return rec.imu_samples.size() < 2
               ? file_at(rec.root + "/" + layout::kImuDir + "/sensor.yaml", rec.imu.line.rate_hz) +
                     ": rate_hz (one gyro sample: its period is 1 / rate_hz)"
               : shown_path(rec.root + "/" + layout::kImuDir + "/data.csv") + ": the median interval between samples, " +
                     format_double(rec.imu_period_s) + " s (the gyro gap is the larger of " +
                     format_double(EstimatorSettings{}.gyro_gap) + " s and " + format_double(kGapPeriods) +
                     " of them: the gyro must sample every " +
                     format_double(config::spec(config::Quantity::kGyroGap).hi / kGapPeriods) + " s or faster)";
  if (setting == "kernels")
    return file_at(cam[0], rec.cam[0].line.intrinsics) + ": the field of view (resolution and intrinsics) sizes the kernels";
  if (setting == "cam[].elevation_scale")  // from the lens model: the intrinsics and the coefficients
    return file_at(cam[0], rec.cam[0].line.intrinsics) + " or " +
           file_at(std::string(layout::kCamDir[1]) + "/sensor.yaml", rec.cam[1].line.intrinsics) +
           ": intrinsics with distortion_coefficients (the lens model)";
  if (setting == "cam[].edges")
    return file_at(cam[0], rec.cam[0].line.distortion) + " or " +
           file_at(std::string(layout::kCamDir[1]) + "/sensor.yaml", rec.cam[1].line.distortion) +
           ": distortion_coefficients";
  if (setting == "width" || setting == "height") return "the working size (--width/--height)";
  return shown_path(rec.root) + ": the estimator configuration derived from it";
}

namespace {

// A kernel outside a view: say which camera is to blame. The kernels are
// centred between the two optical axes, so cameras that look different ways
// (T_BS) push them out of both views; otherwise the camera whose view cannot
// hold them (its field of view and principal point) is, with its view said.
std::string kernels_source(const Recording& rec, const EstimatorSettings& s) {
  auto file = [&](int i) { return rec.root + "/" + layout::kCamDir[i] + "/sensor.yaml"; };
  const double apart = std::remainder(s.cam[1].axis_yaw - s.cam[0].axis_yaw, 2 * M_PI) * 180 / M_PI;
  if (std::fabs(apart) > 10) {
    char deg[32];
    std::snprintf(deg, sizeof deg, "%.1f", std::fabs(apart));
    return file_at(file(0), rec.cam[0].line.T_BS) + " and " + file_at(file(1), rec.cam[1].line.T_BS) +
           ": T_BS: the two cameras' optical axes are " + deg +
           " degrees apart in yaw; they must look the same way (a misalignment of a few degrees at most), and the "
           "kernels, centred between them, fall outside a view";
  }
  // Whether camera i's view holds the kernels alone (the other camera
  // replaced by it), as validate() tries each. A principal point far off the
  // image's centre puts the optical axis, where the kernels are centred, at
  // (or beyond) an edge: a cam1 with cu = -39 px of 40 columns was blamed on
  // cam0, whose intrinsics were right, their focal lengths being the same.
  auto holds_alone = [&](int i) {
    EstimatorSettings t = s;
    t.cam[1 - i] = s.cam[i];
    try {
      (void)to_fixed_config(t);
    } catch (const SettingsError& e) {
      return e.setting() != "kernels";
    }
    return true;
  };
  // "cam1's view spans 41.9 .. 61.3 deg from its optical axis (fu 42.89 px, cu -39 px)"
  auto view = [&](int i) {
    const CameraModel& c = s.cam[i];
    double a = 0, b = 0;
    if (c.edges.size() == static_cast<size_t>(s.width) + 1) {
      a = std::remainder(c.edges.front() - c.axis_yaw, 2 * M_PI);
      b = std::remainder(c.edges.back() - c.axis_yaw, 2 * M_PI);
    } else {
      a = c.u_sign * std::atan((-0.5 - c.cu) / c.fu);
      b = c.u_sign * std::atan((s.width - 0.5 - c.cu) / c.fu);
    }
    char t[160];
    std::snprintf(t, sizeof t,
                  "cam%d's view spans %.1f .. %.1f deg from its optical axis (fu %.4g px, cu %.4g px at %d columns)", i,
                  std::min(a, b) * 180 / M_PI, std::max(a, b) * 180 / M_PI, c.fu, c.cu, s.width);
    return std::string(t);
  };
  const bool holds0 = holds_alone(0), holds1 = holds_alone(1);
  // Neither alone: both are short; one alone: that one; each alone: the
  // two views differ, and the narrower is short of the kernels cam0's sizes.
  const int i = !holds0 ? (holds1 ? 0 : -1) : !holds1 ? 1 : s.cam[1].fu > s.cam[0].fu ? 1 : 0;
  const std::string rule = "the kernels are centred on the optical axis and sized by cam0's view";
  if (i < 0)
    return file_at(file(0), rec.cam[0].line.intrinsics) + " and " + file_at(file(1), rec.cam[1].line.intrinsics) +
           ": intrinsics: " + view(0) + "; " + view(1) + "; " + rule;
  return file_at(file(i), rec.cam[i].line.intrinsics) + ": intrinsics: " + view(i) + "; " + rule +
         (i == 1 ? ": " + view(0) : std::string()) +
         (holds0 && holds1 ? " (the two cameras must see about the same view)" : "");
}

}  // namespace

void check_rig_settings(const Recording& rec, const EstimatorSettings& s) {
  try {
    (void)to_fixed_config(s);
  } catch (const SettingsError& e) {
    const std::string where = e.setting() == "kernels" ? kernels_source(rec, s) : setting_source(rec, e.setting());
    throw RecordingError(where + ": " + e.what());
  }
}

void check_runnable_unwritten(Recording& rec) {
  const std::string cam_csv = rec.root + "/" + layout::kCamDir[0] + "/data.csv";
  const std::string imu_csv = rec.root + "/" + layout::kImuDir + "/data.csv";
  for (int c = 0; c < 2; ++c) check_intrinsics(rec.cam[c], rec.root + "/" + layout::kCamDir[c] + "/sensor.yaml", 0);
  if (rec.imu_samples.empty()) throw recording_error_at(imu_csv, 2, "no gyro samples");
  check_sample_values(rec);
  check_gyro_coverage(rec, imu_csv, cam_csv);
  check_rig_settings(rec, derive_settings(rec, default_working_size(rec)));
}

void check_runnable(const std::string& out) {
  try {
    const Recording rec = load_recording(out);
    check_rig_settings(rec, derive_settings(rec, default_working_size(rec)));
  } catch (const std::exception& e) {
    throw std::runtime_error(out + "/mav0 was written, but lumavel-sim run refuses it: " + e.what());
  }
}

}  // namespace lumavel::host
