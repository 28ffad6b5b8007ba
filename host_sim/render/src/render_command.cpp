// Command line of `lumavel-sim render`.
#include "lumavel/host/render_command.hpp"

#include <cstdint>
#include <cstdio>
#include <memory>
#include <new>
#include <stdexcept>
#include <exception>
#include <filesystem>
#include <string>
#include <vector>

#include "lumavel/host/cli.hpp"
#include "lumavel/host/csv_table.hpp"
#include "lumavel/host/image_io.hpp"
#include "lumavel/host/path_check.hpp"
#include "lumavel/host/recording.hpp"
#include "lumavel/host/recording_error.hpp"
#include "lumavel/host/recording_layout.hpp"
#include "lumavel/host/rig.hpp"
#include "lumavel/host/rig_settings_check.hpp"
#include "lumavel/host/sensor_yaml.hpp"
#include "lumavel/host/render/frame_renderer.hpp"
#include "lumavel/host/render/recording_renderer.hpp"
#include "lumavel/host/render/sensor_synthesis.hpp"
#include "lumavel/host/render/stereo_rig.hpp"
#include "lumavel/host/render/trajectory.hpp"
#include "lumavel/host/render/photometric_presets.hpp"
#include "lumavel/host/render/scenario_loader.hpp"

namespace lumavel::host {
namespace {

const char* const kDescription =
    "render a synthetic recording of a textured scene\n\n"
    "Renders a synthetic stereo camera + gyro recording from a scenario file into\n"
    "OUT/mav0/ in the EuRoC layout (cam0/, cam1/, imu0/, state_groundtruth_estimate0/)\n"
    "of the recording format (docs/recording-format.md). Scenario keys are\n"
    "documented in host_sim/scenarios/README.md. Progress goes to standard error:\n"
    "a bar on a terminal, otherwise a line every few seconds; at the end a summary\n"
    "(frames, drops, samples, background seen) goes to standard output.";

// What run would refuse of the recording (check_runnable_unwritten, with the
// frames' own message first), checked before the first frame is
// rendered on what the render is about to write: its frame times (drops
// taken out), its gyro samples and its rig (sensor.yaml values), by run's own
// rules. A scenario with every frame dropped, no gyro sample within its
// duration (imu offset_s), no baseline or a view the core cannot take was
// rendered whole, then refused (was: up to hours of frames for nothing; the
// check of the written recording, check_runnable, still follows the render).
void check_before_render(const render::Scenario& s, const std::string& out) {
  Recording rec;
  rec.root = out + "/mav0";
  const render::StereoRig rig(s.camera);
  for (int c = 0; c < 2; ++c) rec.cam[c] = render::camera_sensor(s, rig, c);
  rec.imu = render::imu_sensor(s);
  const int n = render::frame_count(s);
  const std::vector<bool> drop = render::dropped_frames(s, n);
  for (int i = 0; i < n; ++i)
    if (!drop[static_cast<size_t>(i)]) rec.frames.push_back({static_cast<uint64_t>(render::frame_stamp_ns(s, i)), {}});
  const render::Trajectory trajectory(s);
  rec.imu_samples = render::synthesize_imu(s, trajectory);
  // Their values too (was: a 100 m/s turn on a 1 mm radius, a 1000 m/s
  // pass taking the ground truth beyond 1e7 m, or gyro noise of 10
  // rad/s/sqrt(Hz) at 100 kHz rendered whole, then 'out/mav0 was written,
  // but lumavel-sim run refuses it').
  rec.groundtruth = render::synthesize_groundtruth(s, trajectory);
  rec.frame_period_s = 1.0 / s.camera.rate_hz;
  rec.imu_period_s = 1.0 / s.imu.rate_hz;
  // No frame before duration_s at all: first_frame_s (mid-exposure time of
  // frame 0) at or after it (was: 'cam0/data.csv:2: no frames (0 before
  // duration_s, all dropped)', a file never written and drops there were not).
  if (n == 0)
    throw render::ScenarioError(shown_path(s.file) + ": first_frame_s = " + format_double(s.camera.first_frame_s) +
                                " s is not before duration_s = " + format_double(s.duration_s) +
                                " s: frames are rendered at first_frame_s + i / rate_hz before duration_s, so the "
                                "recording would hold none (nothing rendered; a later first_frame_s needs a longer "
                                "duration_s or --duration)");
  try {
    if (rec.frames.empty())
      throw recording_error_at(rec.root + "/" + layout::kCamDir[0] + "/data.csv", 2,
                               "no frames (" + std::to_string(n) + " before duration_s, all dropped)");
    check_runnable_unwritten(rec);
  } catch (const RecordingError& e) {
    throw render::ScenarioError(shown_path(s.file) + ": the recording it describes is one lumavel-sim run refuses (nothing "
                                "rendered): " + e.what());
  }
}

struct RenderArgs {
  std::string scenario, out;
  std::string resolution;
  render::Overrides ov;
  render::RenderOptions opt;
  bool force = false, quiet = false;
};

int render_to_folder(RenderArgs& a) {
  // '-' made a folder named '-' (a recording is a folder: it cannot go to
  // standard output), refused as '-' is where other outputs cannot take it.
  if (a.out == "-") throw std::runtime_error("- (OUT): " + why_dash_is_not_an_output("recording", "folder"));
  if (!a.resolution.empty()) {
    cli::parse_size(a.resolution, a.ov.width, a.ov.height);
    if (const std::string why = why_too_many_pixels(a.ov.width, a.ov.height); !why.empty())
      throw cli::UsageError("--resolution: " + a.resolution + " " + why);
  }
  a.opt.progress = !a.quiet;
  render::Scenario s = render::load_scenario(a.scenario);
  render::apply_overrides(s, a.ov);
  // 10^10 frames hung counting them; 3e9 ended, after 25 s, in 'std::bad_alloc'.
  render::check_render_size(s);
  check_before_render(s, a.out);
  const std::string mav0 = a.out + "/mav0";
  std::error_code not_there;  // (symlink_status: a dangling link is there too, the writer cannot make mav0 on it)
  if (std::filesystem::exists(std::filesystem::symlink_status(mav0, not_there))) {
    if (!a.force) throw std::runtime_error(shown_path(mav0) + " already exists (use --force to replace it)");
    // --force deleted the scenario and its photos with the old recording when
    // they lay inside it: the scenario silently (already read), a photo with
    // "photo does not exist" (decoded later). What the render reads is kept.
    std::vector<std::string> reads = {a.scenario};
    for (const render::PlaneSpec& p : s.planes)
      if (p.pattern.kind == render::PatternKind::Photo) reads.push_back(p.pattern.file);
    for (const std::string& r : reads)
      if (lies_inside(r, mav0))
        throw std::runtime_error(shown_path(r) + ": lies inside " + shown_path(mav0) +
                                 ", which --force would delete: the render reads it; write the recording to "
                                 "another folder");
    std::filesystem::remove_all(mav0);
  }
  // A render that fails part way (a full disk) left the frames and tables
  // written so far as OUT/mav0, which could pass for a shorter recording:
  // removed (it is this render's own: an earlier one was refused or removed).
  render::RenderSummary r;
  try {
    r = render::render_recording(s, a.out, a.opt);
  } catch (const std::bad_alloc&) {
    // Each worker holds a frame's radiance (doubles) and its 8-bit image: at
    // 8192x8192 that is 600 MB a thread (was: "error: std::bad_alloc",
    // naming neither the scenario nor the size).
    std::error_code ignored;
    std::filesystem::remove_all(mav0, ignored);
    constexpr double kBytesPerPixel = sizeof(double) + sizeof(uint8_t);
    char b[400];
    std::snprintf(b, sizeof b,
                  "out of memory rendering %dx%d frames with %d thread%s: each thread holds a frame's radiance and "
                  "image, %g bytes a pixel (%.0f MB at this size); render with fewer --threads or at a lower "
                  "--resolution",
                  s.camera.width, s.camera.height, a.opt.threads, a.opt.threads == 1 ? "" : "s", kBytesPerPixel,
                  kBytesPerPixel * s.camera.width * s.camera.height / 1e6);
    throw std::runtime_error(shown_path(s.file) + ": " + b);
  } catch (...) {
    std::error_code ignored;
    std::filesystem::remove_all(mav0, ignored);
    throw;
  }
  if (!a.quiet) {
    std::string bg = "no background visible";
    if (r.max_background_frame >= 0) {
      char buf[96];
      std::snprintf(buf, sizeof buf, "background up to %.1f%% of an image (frame %d)", 100 * r.max_background,
                    r.max_background_frame);
      bg = buf;
    }
    std::printf(
        "%s: %d frame pairs (%d dropped) %dx%d, %zu gyro samples, %zu ground-truth samples, "
        "max %d sub-frames, %s, %.1f s\n",
        shown_path(mav0).c_str(), r.frames - r.dropped, r.dropped, s.camera.width, s.camera.height, r.imu_samples,
        r.groundtruth_samples, r.max_subframes, bg.c_str(), r.seconds);
  }
  check_runnable(a.out);
  return 0;
}

}  // namespace

void add_render_command(cli::Tool& tool) {
  auto a = std::make_shared<RenderArgs>();
  CLI::App* c = tool.command("render", kDescription, [a] { return render_to_folder(*a); });
  c->add_option("SCENARIO", a->scenario, "the scenario file (.yaml)")->required()->type_name("")->check(cli::path_name());
  c->add_option("OUT", a->out, "the recording folder to write (OUT/mav0)")->required()->type_name("")->check(cli::recording_out());
  c->add_option("--resolution", a->resolution, "camera resolution (the field of view is kept), e.g. 40x30")
      ->type_name("WxH")
      ->check(cli::size_wxh(kMaxImageSide, kMaxImageSide));
  c->add_option("--exposure", a->ov.exposure_frames,
                "exposure time as a fraction of the frame period, 0.." + cli::number_text(kMaxExposureFrames) +
                    " (0 = instant)")
      ->type_name("F")
      ->check(cli::number_in(0, kMaxExposureFrames));
  std::string presets;
  for (const auto& p : render::photometric_presets()) presets += std::string("\n    ") + p.name + ": " + p.what;
  c->add_option("--camera-mismatch", a->ov.camera_mismatch,
                "photometric preset for cam0 and cam1, replacing the scenario's photometric block:" + presets)
      ->type_name("PRESET")
      ->check(CLI::Validator(
          [](const std::string& v) {
            return render::find_photometric_preset(v) ? std::string()
                                                      : "'" + shown_path(v) + "' is not a preset (one of: " +
                                                            render::photometric_preset_names() + ")";
          },
          ""));  // (no description: CLI11 would append it to the type name)
  c->add_option("--seed", a->ov.seed, "seed of pixel noise, fixed patterns, gyro noise and random frame drops, >= 0")
      ->type_name("N")
      ->check(cli::whole_number_in(0, 9007199254740992LL));
  c->add_option("--duration", a->ov.duration_s,
                "length in seconds, " + cli::number_text(render::kMinDurationS) + ".." +
                    cli::number_text(render::kMaxDurationS) +
                    " as the scenario's duration_s (the last segment continues if longer)")
      ->type_name("S")
      ->check(cli::number_in(render::kMinDurationS, render::kMaxDurationS));
  c->add_option("--threads", a->opt.threads, "worker threads, 1..256 (default 2)")
      ->type_name("N")
      ->check(cli::whole_number_in(1, 256));
  c->add_flag("--force", a->force, "replace an existing OUT/mav0");
  c->add_flag("-q,--quiet", a->quiet, "no progress on standard error, no summary on standard output");
}

int render_main(int argc, char** argv) { return cli::run_command_alone("lumavel-sim", add_render_command, argc, argv); }

}  // namespace lumavel::host
