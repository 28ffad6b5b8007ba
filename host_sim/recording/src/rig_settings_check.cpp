#include "lumavel/host/rig_settings_check.hpp"

#include "lumavel/host/recording_layout.hpp"

namespace lumavel::host {

std::string setting_source(const Recording& rec, const std::string& setting) {
  const std::string cam[2] = {rec.root + "/" + layout::kCamDir[0] + "/sensor.yaml",
                              rec.root + "/" + layout::kCamDir[1] + "/sensor.yaml"};
  for (int i = 0; i < 2; ++i) {
    const std::string c = "cam[" + std::to_string(i) + "].";
    if (setting == c + "fu" || setting == c + "cu") return cam[i] + ": intrinsics (at the working resolution)";
    if (setting == c + "axis_yaw") return cam[i] + ": T_BS";
  }
  if (setting == "baseline") return cam[0] + " and cam1/sensor.yaml: T_BS (the baseline is cam1's x minus cam0's)";
  if (setting == "frame_period")
    return rec.root + "/" + layout::kCamDir[0] + "/data.csv: the median interval between frames";
  if (setting == "gyro_gap") return rec.root + "/" + layout::kImuDir + "/data.csv: the median interval between samples";
  if (setting == "kernels") return cam[0] + ": the field of view (resolution and intrinsics) sizes the kernels";
  if (setting == "cam[].edges") return cam[0] + " or cam1/sensor.yaml: distortion_coefficients";
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
