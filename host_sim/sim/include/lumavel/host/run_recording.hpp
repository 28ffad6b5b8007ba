// `lumavel-sim run` as a library call: the engine over a recording, frame by
// frame, with the estimates CSV streamed out and the track kept for metrics.
#pragma once
#include <cstdint>
#include <cstdio>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "lumavel/host/engine.hpp"
#include "lumavel/host/file_camera.hpp"
#include "lumavel/host/recording.hpp"
#include "lumavel/host/rig.hpp"
#include "lumavel/host/run_metrics.hpp"

namespace lumavel::host {

// Called with every estimate as it is made (e.g. to send it as a HID report).
using EstimateSink = std::function<void(const EngineEstimate&)>;

struct RunOptions {
  EngineKind engine = EngineKind::kFixed;
  // Working size: up to kMaxWorkWidth x kMaxWorkHeight for lumavel's
  // engines; the vo engine takes any size up to the sensor's.
  WorkingSize size;
  int decode_threads = 2;
  EstimateSink sink;  // optional
  // Estimate as if the lenses were pinhole, whatever sensor.yaml says about
  // distortion: for comparisons, or for real data with doubtful coefficients.
  bool ignore_distortion = false;
  // Correct the lens by per-column tables only (each column's yaw edges and
  // elevation scale from the undistorted geometry), the frames binned as
  // they are: what a device does with the lens tables that `lumavel-read
  // config set` sends it (run --lens-columns). Weaker than undistorting the
  // frames (docs/design.md, "Lens distortion"); for comparisons.
  bool lens_by_columns = false;
  // Learn the gyro's zero-rate offset while the images show the rig still
  // (the default); off: the gyro is taken as is (run --no-gyro-offset-learning).
  bool gyro_offset_learning = true;
  // Learn and correct cam1's offset against cam0 (run --photometric-balance);
  // off by default: the cameras are taken as twins.
  bool photometric_balance = false;
  bool photometric_match = true;
  // The elevation band: by the field of view (config::elevation_band_for)
  // unless forced on or off (run --elevation-band / --no-elevation-band).
  enum class Band { kByView, kOn, kOff } elevation_band = Band::kByView;
  // Clamp the camera that clips less where the other clips (clip_match.hpp;
  // the default); off: the frames as the cameras clipped them
  // (run --no-clip-match).
  bool clip_match = true;
};

struct RunResult {
  std::vector<TrackPoint> track;  // v_true NaN when the recording has no ground truth
  bool has_truth = false;
  size_t frames = 0;
  int width = 0, height = 0;      // working resolution used
  bool lens_distorted = false;    // sensor.yaml gives a distortion (corrected unless ignored)
  int pinhole_outside_px = 0;     // undistorted frames: pixels (both cameras) outside the sensor, edge repeated
  bool elevation_band = false;    // the columns summed one elevation band (by the view or forced)
  double hfov_deg = 0;            // cam0's horizontal field of view
  size_t clip_clamped[2] = {};    // frames of each camera clamped at a clip ceiling (RunOptions::clip_match)
  int clip_lowest[2] = {255, 255};  // the lowest ceiling of each camera
  size_t repeated[2] = {};        // pairs skipped: camera c repeated its last frame (FileStereoCamera::frames_repeated) ...
  size_t first_repeated[2] = {};  // ... the first one's index in rec.frames
  // Frames where both cameras' images clearly moved, the same way or
  // opposite ways (motion_direction.hpp); mirrored: one image is mirrored.
  size_t motion_same = 0, motion_opposite = 0;
  bool mirrored = false;
  // A camera whose images stood still while the other's moved (still_camera()
  // of motion_direction.hpp; -1: none), on motion_alone of motion_counted frames.
  int still_camera = -1;
  size_t motion_alone = 0, motion_counted = 0;
  double wall_s = 0;              // time spent in the frame loop
  double step_s = 0;              // of which in the engine (push_gyro and step): its compute time
};

// Header of the estimates CSV (docs/estimates-csv.md).
extern const char* const kEstimatesHeader;

// The settings `run_recording` uses for `rec`: derive_settings, with the
// distortion tables dropped when options.ignore_distortion is set or the
// frames are undistorted (undistorts_frames), and the
// gyro offset learning as options.gyro_offset_learning says. For the vo
// engine only the working size is used (it is not checked against the core's
// limits; the VO checks it against the sensors).
EstimatorSettings run_settings(const Recording& rec, const RunOptions& options);

// The engine `run_recording` drives: make_engine(options.engine, settings),
// or for the vo engine make_vo_engine from the recording at the settings'
// working size. Throws RecordingError or std::invalid_argument.
std::unique_ptr<Engine> make_run_engine(const Recording& rec, const RunOptions& options,
                                        const EstimatorSettings& settings);

// Whether lumavel's engines get undistorted frames: the default for a
// recording whose sensor.yaml gives a lens distortion (the lens correction;
// not with ignore_distortion, and never for the vo engine, which undistorts
// its feature points itself). run_settings then gives pinhole cameras.
bool undistorts_frames(const Recording& rec, const RunOptions& options);

// Whether either camera's sensor.yaml gives non-zero distortion coefficients.
bool has_lens_distortion(const Recording& rec);

// The end (exclusive) of the gyro samples to push before the frame at t_ns,
// `next` being the first not pushed yet: every sample up to and including the
// first one at or after t_ns, none when that one was pushed for an earlier
// frame (a gyro slower than the frames). The firmware's App::push_gyro_until
// does the same.
size_t gyro_samples_through(const Recording& rec, size_t next, uint64_t t_ns);

// Runs the engine over `rec`. For each frame pair, pushes every gyro sample up
// to and including the first one at or after the frame time, then steps.
// Writes the CSV to `csv` when not null. `progress(done, total)` is called
// now and then when set. Throws RecordingError for a bad frame.
RunResult run_recording(const Recording& rec, const RunOptions& options, std::FILE* csv,
                        const std::function<void(size_t, size_t)>& progress = {});

// Same with a given engine (built for `settings`), e.g. an instrumented one.
// `processing`: what FileStereoCamera does to the frames before binning
// (with `undistort`, `settings` must be pinhole).
RunResult run_recording(const Recording& rec, const EstimatorSettings& settings, Engine& engine,
                        int decode_threads, std::FILE* csv, const std::function<void(size_t, size_t)>& progress = {},
                        const EstimateSink& sink = {}, FrameProcessing processing = {});

// What the frames of a run go through before binning (FileStereoCamera).
FrameProcessing frame_processing(const Recording& rec, const RunOptions& options);

}  // namespace lumavel::host
