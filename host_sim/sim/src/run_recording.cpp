#include "lumavel/host/run_recording.hpp"

#include <charconv>
#include <chrono>
#include <cmath>

#include "lumavel/host/file_camera.hpp"
#include "lumavel/host/groundtruth.hpp"
#include "lumavel/host/motion_direction.hpp"
#include "lumavel/host/recording_layout.hpp"
#include "lumavel/host/rig_settings_check.hpp"
#include "lumavel/host/vo_engine.hpp"
#include "lumavel/units/config_fields.hpp"
#include "native_camera.hpp"

namespace lumavel::host {
namespace {

// Appends a double in its shortest round-trip form.
char* put_double(char* p, char* end, double v) { return std::to_chars(p, end, v, std::chars_format::general).ptr; }

void write_row(std::FILE* f, const EngineEstimate& e, uint64_t t_ns) {
  char buf[256];
  char* const end = buf + sizeof buf;
  char* p = std::to_chars(buf, end, t_ns).ptr;
  *p++ = ',';
  p = put_double(p, end, e.v);
  *p++ = ',';
  p = put_double(p, end, e.distance);
  *p++ = ',';
  p = put_double(p, end, e.heading);
  *p++ = ',';
  p = std::to_chars(p, end, e.status).ptr;
  *p++ = ',';
  p = put_double(p, end, e.gyro_offset);
  *p++ = ',';
  p = put_double(p, end, e.v_direct);
  *p++ = ',';
  p = put_double(p, end, e.texture);
  *p++ = ',';
  p = put_double(p, end, e.v_differential);
  *p++ = ',';
  p = put_double(p, end, e.tof_s);
  *p++ = ',';
  p = put_double(p, end, e.scale);
  *p++ = '\n';
  std::fwrite(buf, 1, static_cast<size_t>(p - buf), f);
}

}  // namespace

const char* const kEstimatesHeader =
    "timestamp_ns,v_xb_mps,distance_m,heading_rad,status,gyro_offset_radps,v_direct_mps,texture,v_differential_mps,"
    "tof_s,scale";

size_t gyro_samples_through(const Recording& rec, size_t next, uint64_t t_ns) {
  const std::vector<ImuSample>& g = rec.imu_samples;
  // The first sample at or after t was pushed already (for an earlier frame:
  // a gyro slower than the frames): none more. Was: one more every frame, so
  // that a 20 Hz gyro under 60 Hz frames ran ahead of them, the estimator
  // held its oldest rate backwards and raised GYRO_GAP on nearly every frame.
  if (next > 0 && g[next - 1].t_ns >= t_ns) return next;
  while (next < g.size())
    if (g[next++].t_ns >= t_ns) break;  // the first sample at or after the frame is the last pushed
  return next;
}

bool has_lens_distortion(const Recording& rec) { return lens_applies(rec.cam[0]) || lens_applies(rec.cam[1]); }

bool undistorts_frames(const Recording& rec, const RunOptions& options) {
  return options.engine != EngineKind::kVo && !options.ignore_distortion && !options.lens_by_columns &&
         has_lens_distortion(rec);
}

FrameProcessing frame_processing(const Recording& rec, const RunOptions& options) {
  FrameProcessing p;
  p.undistort = undistorts_frames(rec, options);
  p.match_clipping = options.clip_match;
  return p;
}

EstimatorSettings run_settings(const Recording& rec, const RunOptions& options) {
  if (options.engine == EngineKind::kVo) {
    // Frames are binned by lumavel::bin_area up to its 160 columns, or used
    // as they are at the sensors' own size; nothing in between (that would
    // need a second binning implementation).
    const CameraSensor& c = rec.cam[0];
    const bool native = options.size.width == c.width && options.size.height == c.height;
    if (options.size.width > kMaxWorkWidth && !native)
      throw recording_error_in(rec.root + "/" + layout::kCamDir[0] + "/sensor.yaml",
                               "the vo engine runs at up to " + std::to_string(kMaxWorkWidth) +
                                   " columns (binned like lumavel's engines) or unbinned at the sensor's resolution " +
                                   std::to_string(c.width) + "x" + std::to_string(c.height) + ", not at " +
                                   std::to_string(options.size.width) + "x" + std::to_string(options.size.height));
    // The same rig rules as lumavel's engines (a 40 m baseline, cu = 1e6 px
    // are refused, naming the file), checked at the default working size.
    check_rig_settings(rec, derive_settings(rec, default_working_size(rec)));
    EstimatorSettings s;  // the VO reads its geometry from the recording itself
    s.width = options.size.width;
    s.height = options.size.height;
    s.frame_period = rec.frame_period_s;
    return s;
  }
  EstimatorSettings s = derive_settings(rec, options.size);
  if (options.ignore_distortion)
    for (CameraModel& c : s.cam) c.edges.clear();  // no edge table: the engines use the pinhole columns
  if (undistorts_frames(rec, options))
    for (CameraModel& c : s.cam) {  // the frames are pinhole frames of the sensor's intrinsics
      c.edges.clear();
      c.elevation_scale.clear();
    }
  s.gyro_offset_learning = options.gyro_offset_learning;
  s.photometric_balance = options.photometric_balance;
  s.photometric_match = options.photometric_match;
  if (options.elevation_band != RunOptions::Band::kByView) s.elevation_band = options.elevation_band == RunOptions::Band::kOn;
  return s;
}

std::unique_ptr<Engine> make_run_engine(const Recording& rec, const RunOptions& options,
                                        const EstimatorSettings& settings) {
  if (options.engine == EngineKind::kVo)
    return make_vo_engine(rec, settings.width, settings.height, options.ignore_distortion);
  return make_engine(options.engine, settings);
}

RunResult run_recording(const Recording& rec, const RunOptions& options, std::FILE* csv,
                        const std::function<void(size_t, size_t)>& progress) {
  const EstimatorSettings settings = run_settings(rec, options);
  std::unique_ptr<Engine> engine;
  try {
    engine = make_run_engine(rec, options, settings);
  } catch (const SettingsError& e) {
    check_rig_settings(rec, settings);  // names the sensor.yaml and key where it can
    throw RecordingError(setting_source(rec, e.setting()) + ": " + e.what());
  }
  RunResult r = run_recording(rec, settings, *engine, options.decode_threads, csv, progress, options.sink,
                              frame_processing(rec, options));
  r.lens_distorted = has_lens_distortion(rec);
  return r;
}

RunResult run_recording(const Recording& rec, const EstimatorSettings& settings, Engine& engine,
                        int decode_threads, std::FILE* csv, const std::function<void(size_t, size_t)>& progress,
                        const EstimateSink& sink, FrameProcessing processing) {
  // Above the binner's 160 columns only the vo engine runs, at the sensors' size (run_settings).
  std::unique_ptr<FileStereoCamera> binned;
  std::unique_ptr<NativeStereoCamera> native;
  if (settings.width > kMaxWorkWidth) native = std::make_unique<NativeStereoCamera>(rec);
  else
    binned = std::make_unique<FileStereoCamera>(rec, settings.width, settings.height, decode_threads, 16,
                                                processing);
  hal::StereoCamera& camera = native ? static_cast<hal::StereoCamera&>(*native) : *binned;
  auto camera_error = [&] { return native ? native->error() : binned->error(); };

  RunResult result;
  result.has_truth = !rec.groundtruth.empty();
  if (binned) result.pinhole_outside_px = binned->pinhole_outside(0) + binned->pinhole_outside(1);
  result.width = settings.width;
  result.elevation_band = settings.elevation_band;
  result.hfov_deg = horizontal_fov(rec.cam[0]) / config::kDeg;
  result.height = settings.height;
  result.track.reserve(rec.frames.size());
  if (csv) std::fprintf(csv, "%s\n", kEstimatesHeader);

  const size_t n = static_cast<size_t>(settings.width) * static_cast<size_t>(settings.height);
  std::vector<uint8_t> buf0(n), buf1(n);
  hal::StereoImage img{0, {buf0.data(), buf1.data()}, 0, 0};
  MotionDirectionCheck motion(settings.width, settings.height, u_sign_of(rec.cam[0]), u_sign_of(rec.cam[1]));
  size_t gyro = 0;
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  Clock::duration in_engine{};
  for (;;) {
    const hal::CaptureStatus st = camera.capture(img);
    if (st == hal::CaptureStatus::kEnd) break;
    if (st == hal::CaptureStatus::kError) throw RecordingError(camera_error());
    const auto engine_start = Clock::now();
    for (const size_t end = gyro_samples_through(rec, gyro, img.t_ns); gyro < end; ++gyro)
      engine.push_gyro(rec.imu_samples[gyro].t_ns, body_yaw_rate(rec.imu, rec.imu_samples[gyro]));
    const EngineEstimate e = engine.step(img.t_ns, buf0.data(), buf1.data());
    in_engine += Clock::now() - engine_start;
    motion.add(buf0.data(), buf1.data());
    if (csv) write_row(csv, e, img.t_ns);
    if (sink) sink(e);
    result.track.push_back(TrackPoint{img.t_ns, e.v, std::nan(""), e.status});
    ++result.frames;
    if (progress && (result.frames & 255) == 0) progress(result.frames, rec.frames.size());
  }
  result.wall_s = std::chrono::duration<double>(Clock::now() - start).count();
  if (binned)
    for (int c = 0; c < 2; ++c) {
      result.clip_clamped[c] = binned->frames_clamped(c);
      result.clip_lowest[c] = binned->lowest_ceiling(c);
      result.repeated[c] = binned->frames_repeated(c);
      result.first_repeated[c] = binned->first_repeated(c);
    }
  result.step_s = std::chrono::duration<double>(in_engine).count();
  result.motion_same = motion.same();
  result.motion_opposite = motion.opposite();
  result.mirrored = motion.mirrored();
  result.still_camera = motion.still_camera();
  if (result.still_camera >= 0) result.motion_alone = motion.alone(1 - result.still_camera);
  result.motion_counted = motion.moved();
  if (result.has_truth) {
    std::vector<uint64_t> t;
    t.reserve(result.track.size());
    for (const TrackPoint& p : result.track) t.push_back(p.t_ns);
    const std::vector<double> v = true_forward_velocity(rec.groundtruth, t);
    for (size_t i = 0; i < v.size(); ++i) result.track[i].v_true = v[i];
  }
  return result;
}

}  // namespace lumavel::host
