// A recording in the EuRoC/ASL layout (docs/recording-format.md),
// loaded and validated in one go: everything that can be checked without
// decoding every frame is checked here; frames are checked as they are decoded.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "lumavel/host/recording_error.hpp"
#include "lumavel/host/sensor_yaml.hpp"

namespace lumavel::host {

struct FramePairEntry {
  uint64_t t_ns = 0;
  std::string path[2];  // image files of cam0, cam1
};

struct ImuSample {
  uint64_t t_ns = 0;
  double w[3] = {0, 0, 0};  // w_RS_S, rad/s, sensor frame
  double a[3] = {0, 0, 0};  // a_RS_S, m/s^2, sensor frame
};

struct GroundTruthSample {
  uint64_t t_ns = 0;
  double p[3] = {0, 0, 0};     // p_RS_R, m
  double q[4] = {1, 0, 0, 0};  // q_RS (w, x, y, z), body to world
  double v[3] = {0, 0, 0};     // v_RS_R, m/s, world frame
  double bw[3] = {0, 0, 0};    // gyro bias
  double ba[3] = {0, 0, 0};    // accelerometer bias
};

// A gyro hole is an interval longer than this many nominal sample periods
// (one missed sample bridged); slow gyros and slow frames get gaps of as many
// periods (rig.hpp's gyro_gap_s and max_gap_s).
constexpr double kGapPeriods = 2.5;

// Gaps are not errors: they are counted here and reported by the tools.
struct GapReport {
  int frame_gaps = 0;          // intervals longer than 1.5 frame periods
  long frames_missing = 0;     // estimated dropped pairs in those intervals
  double longest_frame_gap_s = 0;
  int gyro_holes = 0;          // gyro intervals longer than 2.5 nominal periods
  double longest_gyro_hole_s = 0;
  // Frames whose interval [previous frame, frame] lies partly outside the
  // gyro's span [first sample, last sample]: a gyro that starts late or
  // stops early (each carries GYRO_GAP). A gyro covering none is refused.
  long frames_beyond_gyro = 0;
};

struct Recording {
  std::string root;            // the folder holding cam0/, cam1/, imu0/
  CameraSensor cam[2];
  ImuSensor imu;
  std::vector<FramePairEntry> frames;
  std::vector<ImuSample> imu_samples;
  std::vector<GroundTruthSample> groundtruth;  // empty when absent
  double frame_period_s = 0;   // median cam0 interval (1 / rate_hz for one frame)
  double imu_period_s = 0;     // median imu interval
  GapReport gaps;
  int gyro_glitches = 0;       // gyro values replaced as read glitches (gyro_glitch.hpp) ...
  std::string gyro_glitch_text;  // ... and what the first was ("" for none)
  int frame_glitches = 0;      // frame pairs skipped as timing glitches (frame_glitch.hpp) ...
  std::string frame_glitch_text;  // ... and what the first was ("" for none)
};

// "0 frame gaps (about 0 pairs missing, longest 0.000 s), 0 gyro holes
// (longest 0.000 s)[, N frames beyond the gyro's samples]".
std::string format_gaps(const GapReport& g);
bool has_gaps(const GapReport& g);

// `dir` is REC or REC/mav0. Throws RecordingError naming the file and the
// line or frame of the first problem.
Recording load_recording(const std::string& dir);

// Sets rec.frame_period_s and rec.imu_period_s as load_recording does: the
// median interval of rec.frames and of rec.imu_samples (1 / rate_hz for a
// single one). For a recording about to be written (import-slider).
void set_periods(Recording& rec);

// Counts the frames whose interval the gyro's samples do not hold (into
// rec.gaps.frames_beyond_gyro); throws RecordingError naming `imu_csv` when
// they hold none (stopped before the first frame, started after the last):
// no heading change could be measured. Needs rec.frames, rec.imu_samples
// (neither empty) and rec.imu_period_s; load_recording runs it, and render
// on the recording it is about to write.
void check_gyro_coverage(Recording& rec, const std::string& imu_csv, const std::string& cam_csv);

// The value rules of the imu0 and ground-truth tables, by column (0-based,
// after the timestamp): "" when `v` is within its column's bound, else why
// not ("100267 is beyond +-100000, more than any IMU measures: a corrupt
// value"; the IMU's shown as `text`, as its file holds it). The readers apply
// them, and check_sample_values on a recording about to be written.
std::string why_implausible_imu_value(size_t column, double v, const std::string& text);
std::string why_implausible_groundtruth_value(size_t column, double v);
// Throws RecordingError at the first row of rec.imu_samples or
// rec.groundtruth (line i + 2 of its table under rec.root) that a reader
// would refuse by those rules.
void check_sample_values(const Recording& rec);

// Whether writing `path` would overwrite what the recording is read from: a
// file inside its folder (root), or one of its frames (data.csv may name
// frames elsewhere). Outputs there are refused before a run.
bool overwrites_recording(const Recording& rec, const std::string& path);

// Yaw rate about body z of one imu sample: (R_BS_imu * w_S).z, rad/s.
double body_yaw_rate(const ImuSensor& imu, const ImuSample& s);

}  // namespace lumavel::host
