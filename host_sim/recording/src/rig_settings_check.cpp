#include "lumavel/host/rig_settings_check.hpp"

#include "lumavel/host/recording_layout.hpp"

namespace lumavel::host {

std::string setting_source(const Recording& rec, const std::string& setting) {
  const std::string cam[2] = {rec.root + "/" + layout::kCamDir[0] + "/sensor.yaml",
                              rec.root + "/" + layout::kCamDir[1] + "/sensor.yaml"};
  // "FILE:LINE" of a key, or "FILE" when the recording was not read from files.
  auto at = [](const std::string& file, long line) { return line > 0 ? file + ":" + std::to_string(line) : file; };
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
    return rec.frames.size() < 2 ? cam[0] + ": rate_hz (one frame: the frame period is 1 / rate_hz)"
                                 : rec.root + "/" + layout::kCamDir[0] + "/data.csv: the median interval between frames";
  if (setting == "gyro_gap")
    return rec.imu_samples.size() < 2
               ? rec.root + "/" + layout::kImuDir + "/sensor.yaml: rate_hz (one gyro sample: its period is 1 / rate_hz)"
               : rec.root + "/" + layout::kImuDir + "/data.csv: the median interval between samples";
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
  return rec.root + ": the estimator configuration derived from it";
}

void check_rig_settings(const Recording& rec, const EstimatorSettings& s) {
  try {
    (void)to_fixed_config(s);
  } catch (const SettingsError& e) {
    throw RecordingError(setting_source(rec, e.setting()) + ": " + e.what());
  }
}

}  // namespace lumavel::host
