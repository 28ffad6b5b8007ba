// A render scenario in physical units, as read from YAML (keys documented in
// host_sim/scenarios/README.md). Plain data: the loader validates, the
// renderer trusts it.
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace lumavel::host::render {

enum class LookSide { Left, Right };

// A free-running auto-exposure: the camera's gain wanders slowly, on its own,
// as exp(sigma g(t)); g interpolates (raised cosine) independent unit normal
// values drawn every `interval_s`, per camera. sigma = 0: fixed exposure.
struct AutoExposureSpec {
  double sigma = 0;       // rms of the log gain
  double interval_s = 2;  // time between independent values
};

// One camera's photometric response, applied to the radiance before pixel
// noise, rounding and clipping (photometric_response.hpp has the formula).
// These defaults are an ideal camera: the renderer's output is then the
// radiance itself, byte for byte.
struct PhotometricSpec {
  double gain = 1;             // relative exposure x analog gain
  double black_level = 0;      // gray levels added
  double vignetting[2] = {0, 0};  // v1, v2: 1 + v1 r^2 + v2 r^4, r = 1 at the image corner
  double prnu = 0;             // per-pixel gain, sigma (relative)
  double dsnu = 0;             // per-pixel offset, sigma (gray levels)
  double column_gain = 0;      // per-column gain, sigma (relative)
  double column_offset = 0;    // per-column offset, sigma (gray levels)
  double gamma = 1;            // response 255 (x / 255)^gamma
  AutoExposureSpec auto_exposure;
  bool ideal() const {
    return gain == 1.0 && black_level == 0.0 && vignetting[0] == 0.0 && vignetting[1] == 0.0 &&
           prnu == 0.0 && dsnu == 0.0 && column_gain == 0.0 && column_offset == 0.0 && gamma == 1.0 &&
           auto_exposure.sigma == 0.0;
  }
};

struct CameraSpec {
  int width = 640, height = 480;
  double hfov_deg = 50, vfov_deg = 40;
  double rate_hz = 60;
  double exposure_frames = 0;   // exposure time / frame period
  double baseline_m = 0.08;     // distance between optical centres
  double misalignment_deg = 0;  // yaw of cam1 relative to cam0 (CCW positive)
  LookSide look = LookSide::Left;
  bool cam1_ahead = true;       // cam1 sits at +h/2 on body x, cam0 at -h/2
  double rig_yaw_deg = 0;       // yaw of both cameras away from orthogonal
  double first_frame_s = 0;     // mid-exposure time of frame 0
  std::array<double, 4> distortion{};  // radial-tangential k1, k2, p1, p2; 0 = pinhole
  std::array<PhotometricSpec, 2> photometric{};  // cam0, cam1
  std::string photometric_preset;  // name it started from ("" = none); for messages only
};

enum class PatternKind { Uniform, Sinusoid, Checker, Photo };
enum class Tiling { None, Mirror, Repeat };

struct PatternSpec {
  PatternKind kind = PatternKind::Uniform;
  double value = 128;  // uniform gray level
  // sinusoid: mean + amplitude * combine(sin(2 pi s/Ps + ph_s), sin(2 pi t/Pt + ph_t))
  double mean = 128, amplitude = 127;
  double period_h_m = 0.5, period_v_m = 0.5;
  double phase_h_deg = 0, phase_v_deg = 0;
  bool product = false;  // false: average of the two sines; true: product
  // checker: squares of `square_m`, levels low/high, origin at the plane corner
  double square_m = 0.5, low = 0, high = 255;
  // photo: file (PNG/JPEG/PGM), physical size of one copy, tiling beyond it
  std::string file;
  std::string file_at;  // "SCENARIO:LINE" of 'file:', named in the photo's errors (decoded later)
  double width_m = 1, height_m = 1;
  Tiling tiling = Tiling::None;
  double offset_h_m = 0, offset_v_m = 0;  // photo origin on the plane
};

// A vertical rectangle: its base runs from `from` to `to` (world x, y), it
// spans z in [z_min, z_max]. Plane coordinates: s from `from` towards `to`,
// v from z_max downwards, so the texture reads upright from the side where
// from -> to runs left to right.
struct PlaneSpec {
  std::string name;
  double from[2] = {0, 0}, to[2] = {1, 0};
  double z_min = -1, z_max = 1;
  PatternSpec pattern;
};

enum class SegmentKind { Straight, Arc };
enum class SpeedProfile { Linear, Smooth };

struct SegmentSpec {
  SegmentKind kind = SegmentKind::Straight;
  double duration_s = 1;
  double v0 = 0, v1 = 0;     // speed along body x at start and end, m/s (signed)
  SpeedProfile profile = SpeedProfile::Linear;
  double curvature = 0;      // 1/m, positive = left turn (CCW)
};

struct TrajectorySpec {
  double x0 = 0, y0 = 0, z = 0, heading0_deg = 0;
  std::vector<SegmentSpec> segments;
};

struct LightingSpec {
  double flicker_hz = 0;  // frequency of the intensity ripple
  double flicker_amplitude = 0;  // relative, gain = 1 + a sin(2 pi f t + ph)
  double flicker_phase_deg = 0;
  std::vector<std::pair<double, double>> dark;  // [t0, t1) lights off, s
};

struct ImuSpec {
  double rate_hz = 200;
  double offset_s = 0.0013;          // first sample time (not frame-synchronous)
  double gyro_noise_density = 0;     // rad/s/sqrt(Hz), white
  double gyro_random_walk = 0;       // rad/s^2/sqrt(Hz), written to sensor.yaml only
  double gyro_bias_z = 0;            // rad/s, constant
  double accel_noise_density = 0;    // m/s^2/sqrt(Hz)
};

// Rig vibration: the body pitches, rolls and heaves about its planar path,
// each axis a sum of sinusoids over [freq_lo_hz, freq_hi_hz] with phases
// drawn from the scenario seed (vibration.hpp). Amplitudes are rms; all zero
// (the default, no 'vibration:' block) leaves the body level.
struct VibrationSpec {
  double pitch_rms_deg = 0;  // about body y (left): positive = nose down
  double roll_rms_deg = 0;   // about body x (forward): positive = right side down
  double heave_rms_m = 0;    // along world z
  double freq_lo_hz = 2, freq_hi_hz = 15;
  bool none() const { return pitch_rms_deg == 0.0 && roll_rms_deg == 0.0 && heave_rms_m == 0.0; }
};

// The loader's limits for 'vibration:' (what a wheeled rig plausibly does;
// above half the frame rate the motion aliases in the images, allowed).
constexpr double kMaxVibrationAngleDeg = 20;  // pitch_deg, roll_deg (rms)
constexpr double kMaxVibrationHeaveM = 0.5;   // heave_m (rms)
constexpr double kMinVibrationHz = 0.01;      // frequency_hz
constexpr double kMaxVibrationHz = 100;

// A scenario's duration_s, given in the file or by render --duration: one
// rule for both (was: the file took [1e-3, 1e6] s, the option (0, 1e6] s).
constexpr double kMinDurationS = 1e-3;
constexpr double kMaxDurationS = 1e6;

struct Scenario {
  std::string file;  // where it was read from (messages)
  std::string description;
  double duration_s = 4;  // kMinDurationS..kMaxDurationS
  uint64_t seed = 1;
  int64_t start_ns = 1000000000;  // timestamp of scenario time 0
  double groundtruth_rate_hz = 200;
  CameraSpec camera;
  TrajectorySpec trajectory;
  double background = 128;
  std::vector<PlaneSpec> planes;
  LightingSpec lighting;
  double pixel_noise_sigma = 0;  // gray levels
  ImuSpec imu;
  std::vector<int> dropped_frames;
  double drop_rate = 0;          // probability that a frame pair is lost
  VibrationSpec vibration;       // none: a level body on its planar path
};

}  // namespace lumavel::host::render
