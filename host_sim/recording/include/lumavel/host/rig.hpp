// Rig geometry from the two camera sensor.yaml files: the estimator settings
// for a working resolution (intrinsics scaled, optical-axis yaw, image
// orientation, baseline, frame period, gyro gap).
#pragma once
#include "lumavel/core/limits.hpp"
#include "lumavel/host/lens_distortion.hpp"
#include "lumavel/host/recording.hpp"
#include "lumavel/host/settings.hpp"

namespace lumavel::host {

struct WorkingSize {
  int width = kDefaultColumns;
  int height = kDefaultRows;  // forced to 1 for line-scan input (sensor height 1)
};

// Working resolution limits: those of the firmware core (limits.hpp).
constexpr int kMinWorkWidth = kMinColumns, kMaxWorkWidth = kMaxColumns, kMaxWorkHeight = kMaxRows;

// The default working size for a recording: 40x30, or cam0's own size on an
// axis where it is smaller (limits.hpp, default_columns/default_rows).
WorkingSize default_working_size(const Recording& rec);

// The camera's horizontal field of view (rad) from its width and focal length.
double horizontal_fov(const CameraSensor& c);

// The sensor's radial-tangential distortion applies: a coefficient is not 0.
bool lens_applies(const CameraSensor& c);
// k1, k2, p1, p2 of the sensor (missing ones 0).
LensDistortion lens_of(const CameraSensor& c);

// +1 or -1: the sign of d(body yaw)/du of the camera's image
// (CameraModel::u_sign: -1 upright, +1 upside down), from its T_BS.
int u_sign_of(const CameraSensor& c);

// Camera model of one camera at the working width. Throws RecordingError
// naming the sensor.yaml when the optical axis is not horizontal.
CameraModel derive_camera(const CameraSensor& c, int work_width, const std::string& yaml_path);

// Body yaw of the working columns' edges through the sensor's
// radial-tangential distortion (empty when the coefficients are all zero:
// the pinhole model applies).
// Throws RecordingError naming the sensor.yaml when its radial-tangential
// distortion cannot be inverted over the image (k1 = 1e10: no undistorted
// point maps to the outer pixels) or folds the principal row's columns.
// load_recording checks both cameras, so every command and engine refuses it.
void check_lens_invertible(const CameraSensor& c, const std::string& yaml_path);

// Each edge's yaw is the mean over the rows of the elevation band that every
// column sees (a distorted column's rows look at different yaws).
std::vector<double> undistorted_column_edges(const CameraSensor& c, int work_width, double axis_yaw, int u_sign);
// Each working column's elevation scale through the lens (CameraModel::
// elevation_scale); empty when the pinhole model applies.
std::vector<double> lens_elevation_scales(const CameraSensor& c, int work_width);

// The gyro gap for a gyro sampled every `imu_period_s`: the settings'
// default, or kGapPeriods nominal periods for a slow gyro, so that a slow
// gyro does not look like a gyro gap at every frame.
double gyro_gap_s(double imu_period_s);

// How far cam1's focal lengths are from cam0's: the larger of |fu1/fu0 - 1|
// and |fv1/fv0 - 1| (the two sensors have one resolution). lumavel reads
// both cameras' column sums as views of the same rows of the scene: a
// mismatch reads as motion. Measured on robustness_wall at 40x30 (E 1.0 %
// with twin cameras): 0.6 % -> E 4.6 %, 1.1 % -> 7.0 %, 2.2 % -> 11.9 %,
// 10 % -> 68.6 %, with no status flag. run warns from kFocalMismatchWarn on.
double focal_length_mismatch(const Recording& rec);
constexpr double kFocalMismatchWarn = 0.005;

// The longest frame interval the observer bridges for frames every
// `frame_period_s`: the settings' default (0.5 s), or kGapPeriods nominal periods for
// slow frames (one dropped pair bridged, as at the default's 60 Hz), at most
// the core's 4 s. Was the default always: at 2 Hz a jitter of a microsecond
// restarted the observer on every frame, and below 2 Hz (a frame period of
// 0.5..1 s, which the core takes) run refused the recording over "max gap =
// 0.5 s", a setting the recording does not give.
double max_gap_s(double frame_period_s);

// Throws RecordingError, naming a sensor.yaml's resolution line, when `size`
// is larger than a camera's sensor on either axis: frames are binned down,
// never up. derive_settings checks it after taking a line-scan sensor's
// height to 1; a size the user asked for is checked as given (run --height 2
// on a line scan was worked at height 1, silently).
// `asked_by` is what the user chose the size with, named in the refusal's
// hint ("--width/--height" for run, "--width" for calibrate, "<width>
// <height>" for lumavel_recording_to_stream).
void check_bins_down(const Recording& rec, WorkingSize size, const std::string& asked_by = "working size");

// Full settings; throws RecordingError for a working size the sensors cannot
// be binned to, or for cameras that do not share one resolution.
EstimatorSettings derive_settings(const Recording& rec, WorkingSize size);

}  // namespace lumavel::host
