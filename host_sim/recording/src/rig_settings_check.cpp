#include "lumavel/host/rig_settings_check.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "lumavel/host/path_check.hpp"
#include "lumavel/host/recording_error.hpp"
#include "lumavel/host/recording_layout.hpp"
#include "lumavel/host/rig.hpp"
#include "lumavel/host/sensor_yaml.hpp"

namespace lumavel::host {

std::string setting_source(const Recording& rec, const std::string& setting) {
  const std::string cam[2] = {rec.root + "/" + layout::kCamDir[0] + "/sensor.yaml",
                              rec.root + "/" + layout::kCamDir[1] + "/sensor.yaml"};
  // "FILE:LINE" of a key, or "FILE" when the recording was not read from files.
  // (through shown_path, as recording_error_at shows a file)
  auto at = [](const std::string& file, long line) {
    return line > 0 ? shown_path(file) + ":" + std::to_string(line) : shown_path(file);
  };
  for (int i = 0; i < 2; ++i) {
    const std::string c = "cam[" + std::to_string(i) + "].";
    if (setting == c + "fu" || setting == c + "cu")
      return at(cam[i], rec.cam[i].line.intrinsics) + ": intrinsics (at the working resolution)";
    if (setting == c + "axis_yaw") return at(cam[i], rec.cam[i].line.T_BS) + ": T_BS";
  }
  if (setting == "baseline")
    return at(cam[0], rec.cam[0].line.T_BS) + " and " + at(std::string(layout::kCamDir[1]) + "/sensor.yaml",
                                                           rec.cam[1].line.T_BS) +
           ": T_BS (the baseline is cam1's x minus cam0's)";
  // With one frame or one gyro sample the period is 1 / rate_hz (load_recording).
  if (setting == "frame_period")
    return rec.frames.size() < 2
               ? at(cam[0], rec.cam[0].line.rate_hz) + ": rate_hz (one frame: the frame period is 1 / rate_hz)"
               : shown_path(rec.root + "/" + layout::kCamDir[0] + "/data.csv") + ": the median interval between frames";
  if (setting == "gyro_gap")
    return rec.imu_samples.size() < 2
               ? at(rec.root + "/" + layout::kImuDir + "/sensor.yaml", rec.imu.line.rate_hz) +
                     ": rate_hz (one gyro sample: its period is 1 / rate_hz)"
               : shown_path(rec.root + "/" + layout::kImuDir + "/data.csv") + ": the median interval between samples";
  if (setting == "kernels")
    return at(cam[0], rec.cam[0].line.intrinsics) + ": the field of view (resolution and intrinsics) sizes the kernels";
  if (setting == "cam[].elevation_scale")  // from the lens model: the intrinsics and the coefficients
    return at(cam[0], rec.cam[0].line.intrinsics) + " or " +
           at(std::string(layout::kCamDir[1]) + "/sensor.yaml", rec.cam[1].line.intrinsics) +
           ": intrinsics with distortion_coefficients (the lens model)";
  if (setting == "cam[].edges")
    return at(cam[0], rec.cam[0].line.distortion) + " or " +
           at(std::string(layout::kCamDir[1]) + "/sensor.yaml", rec.cam[1].line.distortion) +
           ": distortion_coefficients";
  if (setting == "width" || setting == "height") return "the working size (--width/--height)";
  return shown_path(rec.root) + ": the estimator configuration derived from it";
}

namespace {

// A kernel outside a view: say which camera is to blame. The kernels are
// centred between the two optical axes, so cameras that look different ways
// (T_BS) push them out of both views; otherwise the narrower view is short.
std::string kernels_source(const Recording& rec, const EstimatorSettings& s) {
  auto file = [&](int i) { return rec.root + "/" + layout::kCamDir[i] + "/sensor.yaml"; };
  auto at = [](const std::string& f, long line) {
    return line > 0 ? shown_path(f) + ":" + std::to_string(line) : shown_path(f);
  };
  const double apart = std::remainder(s.cam[1].axis_yaw - s.cam[0].axis_yaw, 2 * M_PI) * 180 / M_PI;
  if (std::fabs(apart) > 10) {
    char deg[32];
    std::snprintf(deg, sizeof deg, "%.1f", std::fabs(apart));
    return at(file(0), rec.cam[0].line.T_BS) + " and " + at(file(1), rec.cam[1].line.T_BS) +
           ": T_BS: the two cameras' optical axes are " + deg +
           " degrees apart in yaw; they must look the same way (a misalignment of a few degrees at most), and the "
           "kernels, centred between them, fall outside a view";
  }
  const int narrow = s.cam[1].fu > s.cam[0].fu ? 1 : 0;  // the longer focal length sees less
  return at(file(narrow), rec.cam[narrow].line.intrinsics) +
         ": the field of view (resolution and intrinsics) sizes the kernels";
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
