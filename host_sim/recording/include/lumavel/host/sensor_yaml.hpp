// EuRoC/ASL sensor.yaml files (camera and imu), read with yaml-cpp and written
// with the exact EuRoC keys. Errors name the file and the line.
#pragma once
#include <array>
#include <string>
#include <vector>

#include "lumavel/core/binning.hpp"

namespace lumavel::host {

// 4x4 row-major pose of a sensor in the body frame: p_B = T_BS * p_S.
using Pose = std::array<double, 16>;
Pose identity_pose();

struct CameraSensor {
  double rate_hz = 0;
  int width = 0, height = 0;           // resolution: [width, height]
  double fu = 0, fv = 0, cu = 0, cv = 0;  // intrinsics, pixels, pixel 0 centre = 0
  std::string distortion_model = "radial-tangential";
  std::vector<double> distortion;      // [k1, k2, p1, p2], kept for lens models
  Pose T_BS = identity_pose();
  double exposure_s = -1;              // optional; < 0 when absent
  std::string comment;                 // optional
  // The line of each key in the file it was read from (0: not from a file),
  // so that a value the firmware cannot take is blamed on its line.
  struct Lines {
    long rate_hz = 0, resolution = 0, intrinsics = 0, distortion = 0, T_BS = 0;
  } line;
};

struct ImuSensor {
  double rate_hz = 0;
  Pose T_BS = identity_pose();
  double gyroscope_noise_density = -1;  // optional; < 0 when absent
  double gyroscope_random_walk = -1;    // optional; < 0 when absent
  std::string comment;
  struct Lines {  // as CameraSensor's
    long rate_hz = 0;
  } line;
};

// The ranges of values a sensor.yaml gives that lumavel reads but does not
// estimate with (the translations of T_BS other than the cameras' x,
// exposure_s, the gyro's noise model; rate_hz when data.csv times the
// samples): a value beyond them is a damaged file, refused at its line like
// any other damaged value, not taken silently. Generous: what a sensor on a
// vehicle, or a rendered one, can have.
constexpr double kMaxRateHz = 1e6;           // rate_hz: a period of 1 us or more
constexpr double kMaxSensorOffsetM = 100;    // each T_BS translation component: a sensor on the vehicle
constexpr double kMaxExposureFrames = 10;    // exposure_s <= 10 / rate_hz (the renderer's longest blur)
constexpr double kMaxGyroNoiseDensity = 10;  // gyroscope_noise_density, rad/s/sqrt(Hz)
constexpr double kMaxGyroRandomWalk = 10;    // gyroscope_random_walk, rad/s^2/sqrt(Hz)

// The intrinsics' own rules, checked as they are read, before the lens
// model uses them (a principal point of 1e5 px would otherwise be blamed on
// the distortion coefficients): cu within [-width, 2 width], cv within
// [-height, 2 height], fv/fu 0.5..2. Throws RecordingError naming FILE:LINE.
void check_intrinsics(const CameraSensor& c, const std::string& file, long line);

// "" when a frame of width x height pixels can be binned to a working size
// (lumavel::bin_area: at most kMaxBinPixels, 4096x4096); otherwise why not:
// "is N pixels: lumavel bins frames of at most ...". A sensor.yaml's
// resolution, a scenario's and render --resolution are held to it.
inline std::string why_too_many_pixels(double width, double height) {
  if (width * height <= kMaxBinPixels) return "";
  return "is " + std::to_string(static_cast<long long>(width * height)) + " pixels: lumavel bins frames of at most " +
         std::to_string(kMaxBinPixels) + " pixels (4096x4096: it sums a frame in 32 bits)";
}

// Throw RecordingError naming `path` (and the line when the problem has one).
CameraSensor read_camera_yaml(const std::string& path);
ImuSensor read_imu_yaml(const std::string& path);

void write_camera_yaml(const std::string& path, const CameraSensor& c);
void write_imu_yaml(const std::string& path, const ImuSensor& s);

}  // namespace lumavel::host
