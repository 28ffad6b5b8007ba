#include "run_command.hpp"

#include <chrono>
#include <cmath>
#include <csignal>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "lumavel/core/clip_match.hpp"
#include "lumavel/core/status.hpp"
#include "lumavel/host/cli.hpp"
#include "lumavel/host/decimal_text.hpp"
#include "lumavel/host/file_config_store.hpp"
#include "lumavel/host/hid_link.hpp"
#include "lumavel/host/hid_sender.hpp"
#include "lumavel/host/output_file.hpp"
#include "lumavel/host/path_check.hpp"
#include "lumavel/host/progress.hpp"
#include "lumavel/host/recording_layout.hpp"
#include "lumavel/host/motion_direction.hpp"
#include "lumavel/host/run_recording.hpp"
#include "lumavel/host/track_plot.hpp"
#include "lumavel/host/vo/stereo_rig.hpp"
#include "lumavel/protocol/device_config.hpp"
#include "lumavel/units/config_fields.hpp"

namespace lumavel::host {
namespace {

const char* const kRunDescription =
    "run the estimator over a recording, write the estimates CSV\n\n"
    "Runs the estimator over the recording REC (the recording format:\n"
    "docs/recording-format.md; REC or REC/mav0) and writes the estimates CSV\n"
    "(docs/estimates-csv.md): one row per frame pair,\n"
    "  timestamp_ns,v_xb_mps,distance_m,heading_rad,status,gyro_offset_radps,v_direct_mps,texture,\n"
    "  v_differential_mps,tof_s,scale\n"
    "\n"
    "A summary goes to standard error: frames, gaps, the working size, the frames\n"
    "each status flag was raised on, whether the lens distortion was corrected or\n"
    "ignored and, with ground truth (state_groundtruth_estimate0), the paper's error\n"
    "E (eq. 22), L1 and RMS errors, worst and mean error after the first second (or\n"
    "why there is no figure); the gyro zero-rate offset learned at standstill\n"
    "(or why none was); last, what the photometric match learned of how cam1's\n"
    "black level and vignetting differ from cam0's (docs/design.md).";

// The vo engine's native-resolution path: the recording's sensor size bounds
// it further (run_settings).
constexpr int kMaxVoWorkSize = 2048;

struct RunArgs {
  std::string rec;
  std::string engine = "fixed";
  std::string output;
  std::string plot;
  std::string hid;
  std::string hid_config;
  double hid_linger_s = 0;
  int hid_wait_ms = -1;  // -1: HidSender's default
  int width = 0, height = 0;  // 0: the default working size for the recording
  bool quiet = false;
  bool ignore_distortion = false;
  bool lens_columns = false;
  bool no_gyro_offset_learning = false;
  bool photometric_balance = false;
  bool no_photometric_match = false;
  bool no_clip_match = false;
  bool elevation_band = false;
  bool no_elevation_band = false;
};

// --hid-linger: seconds 0..1e9 (about 32 years: the clock's deadline must
// not overflow, which ended 1e10 s at once), or -1 for "until interrupted".
CLI::Validator linger_seconds() {
  return CLI::Validator(
      [](std::string& s) -> std::string {
        const DecimalText d = read_decimal(s);  // decimal only, as every number the tools read
        const double v = d.value;
        if (d.problem != DecimalText::Problem::kNone || (v < 0 && v != -1))
          return "must be a number of seconds >= 0, or -1 (until interrupted), not '" + s + "'";
        if (v > 1e9) return "must be at most 1e9 seconds (about 32 years), or -1 (until interrupted), not '" + s + "'";
        return {};
      },
      "");
}

CLI::Validator host_link_spec() {
  return CLI::Validator([](std::string& s) { return check_host_link_spec(s); }, "");
}

CLI::Validator engine_kind() {
  return CLI::Validator(
      [](std::string& s) -> std::string {
        try {
          parse_engine_kind(s);
          return {};
        } catch (const std::exception& e) {
          return e.what();
        }
      },
      "");
}

// "path/to/REC/" or "path/to/REC/mav0" -> "REC".
// The recording's folder name (REC, not mav0), as the path resolves: "."
// or "mav0" run from inside a recording name the recording too.
std::string recording_name(const std::string& path) {
  std::error_code ec;
  std::filesystem::path p = std::filesystem::absolute(path, ec);
  if (ec) p = path;
  p = p.lexically_normal();
  if (!p.has_filename()) p = p.parent_path();  // a trailing separator
  if (p.filename() == "mav0" && p.has_parent_path() && p.parent_path().has_filename()) p = p.parent_path();
  const std::string name = p.filename().string();
  return name.empty() || name == "." || name == ".." ? std::string("recording") : name;
}

std::string default_plot_path(const RunArgs& a) {
  std::string dir;
  // Beside a file only: not beside a device or a pipe (-o /dev/null, /dev/stdout).
  std::error_code ec;
  const auto kind = std::filesystem::status(a.output, ec).type();
  const bool beside = kind == std::filesystem::file_type::not_found || kind == std::filesystem::file_type::regular;
  const size_t s = a.output.find_last_of('/');
  if (beside && s != std::string::npos) dir = a.output.substr(0, s + 1);
  return dir + recording_name(a.rec) + "_estimates.svg";
}

// Where the working size came from, when not from --width/--height.
std::string working_size_origin(const RunArgs& a, const Recording& rec) {
  if (a.width > 0 || a.height > 0) return "";
  const WorkingSize d = default_working_size(rec);
  const bool own = d.width < kDefaultColumns || d.height < kDefaultRows;
  if (!own) return " (the default)";
  return " (the default " + std::to_string(kDefaultColumns) + "x" + std::to_string(kDefaultRows) +
         " cut to the " + std::to_string(rec.cam[0].width) + "x" + std::to_string(rec.cam[0].height) + " sensor)";
}

const char* lens_line(bool distorted, bool ignored, bool by_columns) {
  if (!distorted) return "lens: no distortion in sensor.yaml (--ignore-distortion and --lens-columns change nothing)";
  if (by_columns && !ignored)
    return "lens: radial-tangential distortion corrected by column tables only (--lens-columns: the device's "
           "correction; frames binned as they are)";
  return ignored ? "lens: distortion IGNORED (--ignore-distortion): columns read as pinhole"
                 : "lens: radial-tangential distortion corrected (each frame resampled onto the pinhole of sensor.yaml's "
                   "intrinsics before binning)";
}

// The offset the run ended with, and for how long the images showed the rig
// still (status bit kStatusStill: the offset was being learned).
constexpr double kDegPerRad = 57.29577951308232;

std::string gyro_offset_line(EngineKind engine, bool learning, const std::vector<TrackPoint>& track,
                             double last_offset) {
  if (engine == EngineKind::kVo) return "gyro offset: not learned (the vo engine takes the gyro as it reads)";
  if (!learning) return "gyro offset: not learned (--no-gyro-offset-learning)";
  double still_s = 0;
  for (size_t i = 1; i < track.size(); ++i)
    if (track[i].status & kStatusStill) still_s += static_cast<double>(track[i].t_ns - track[i - 1].t_ns) * 1e-9;
  if (still_s == 0) return "gyro offset: not learned (no standstill seen)";
  char buf[160];
  std::snprintf(buf, sizeof buf, "gyro offset learned: %+.4f deg/s (%+.3e rad/s), rig still for %.2f s",
                last_offset * kDegPerRad, last_offset, still_s);
  return buf;
}

// Which frames the clip ceiling clamped, or why none.
std::string clip_line(const RunOptions& o, const RunResult& r) {
  if (!o.clip_match) return "clip match: off (--no-clip-match): the frames binned as the cameras clipped them";
  if (o.engine == EngineKind::kVo && r.width > kMaxWorkWidth) return "clip match: not applied (vo at the sensors' size)";
  if (r.clip_clamped[0] == 0 && r.clip_clamped[1] == 0)
    return "clip match: no frame where the brighter camera clipped on more than " +
           std::to_string(kClipShareRatio) + "x the other's share of pixels";
  std::string s = "clip match:";
  const char* sep = "";
  for (int c = 0; c < 2; ++c)
    if (r.clip_clamped[c] > 0)
      s += std::string(std::exchange(sep, ";")) + " cam" + std::to_string(c) + " clamped where cam" +
           std::to_string(1 - c) + " clipped on " + std::to_string(r.clip_clamped[c]) + " of " +
           std::to_string(r.frames) + " frames (ceiling down to " + std::to_string(r.clip_lowest[c]) + ")";
  return s;
}

// What the photometric match mapped cam1 onto cam0 with at the end (it
// multiplies cam1's column sums by 1 + a1 x + a2 x^2 after removing its black
// level): cam1's black level over cam0's, and its response against cam0's at
// the image's left and right edges (x = -1, +1), the centre's taken as equal.
std::string photometric_line(EngineKind engine, bool matching, const double p[3]) {
  if (engine == EngineKind::kVo) return "photometric match: none (the vo engine matches features)";
  if (!matching) return "photometric match: off (--no-photometric-match): the cameras taken as twins";
  if (p[0] == 0 && p[1] == 0 && p[2] == 0)
    return "photometric match: the cameras taken as twins (no difference found that the match explains)";
  char buf[220];
  std::snprintf(buf, sizeof buf,
                "photometric match: cam1's black level %+.2f DN over cam0's; its response at the left / right "
                "edge %+.1f / %+.1f %% of cam0's",
                p[2], 100 * (1 / (1 + p[1] - p[0]) - 1), 100 * (1 / (1 + p[1] + p[0]) - 1));
  return buf;
}

volatile std::sig_atomic_t g_stop_linger = 0;
void on_linger_signal(int) { g_stop_linger = 1; }

// Keeps answering feature reports after the last estimate, so a host can
// read info and get/set the configuration of a finished run.
void linger(HidSender& hid, double seconds) {
  g_stop_linger = 0;
  std::signal(SIGINT, on_linger_signal);
  std::signal(SIGTERM, on_linger_signal);
  const auto end = std::chrono::steady_clock::now() +
                   std::chrono::microseconds(static_cast<int64_t>(seconds < 0 ? 0 : seconds * 1e6));
  while (!g_stop_linger && (seconds < 0 || std::chrono::steady_clock::now() < end)) {
    hid.poll();
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  std::signal(SIGINT, SIG_DFL);
  std::signal(SIGTERM, SIG_DFL);
}

int run(const RunArgs& a) {
  if (a.hid.empty() && (!a.hid_config.empty() || a.hid_linger_s != 0 || a.hid_wait_ms >= 0))
    throw cli::UsageError("--hid-config, --hid-wait-ms and --hid-linger need --hid SPEC");
  RunOptions options;
  options.engine = parse_engine_kind(a.engine);
  if (options.engine != EngineKind::kVo && a.width > kMaxWorkWidth)
    throw cli::UsageError("--width: must be a whole number in " + std::to_string(kMinWorkWidth) + ".." +
                          std::to_string(kMaxWorkWidth) + " (the firmware core's limit; --engine vo goes up to the "
                          "sensor's width), not '" + std::to_string(a.width) + "'");
  if (options.engine != EngineKind::kVo && a.height > kMaxWorkHeight)
    throw cli::UsageError("--height: must be a whole number in 1.." + std::to_string(kMaxWorkHeight) +
                          " (the firmware core's limit; --engine vo goes up to the sensor's height), not '" +
                          std::to_string(a.height) + "'");
  // What the vo engine does not do, asked of it (was: taken, ignored without
  // a word; --lens-columns even said the lens was corrected by column tables).
  // The options that only turn a step off (--no-photometric-match, ...) ask
  // nothing of it.
  if (options.engine == EngineKind::kVo) {
    const std::pair<bool, const char*> asked[] = {
        {a.lens_columns, "--lens-columns: the vo engine has no column tables (it undistorts each frame, or takes the "
                         "lens as pinhole with --ignore-distortion)"},
        {a.photometric_balance, "--photometric-balance: the vo engine balances no kernels (it matches features)"},
        {a.elevation_band, "--elevation-band: the vo engine sums no columns (it tracks features)"}};
    for (const auto& [given, why] : asked)
      if (given) throw cli::UsageError(std::string(why) + "; the option is for --engine fixed or float");
  }
  if (options.engine == EngineKind::kVo && a.height > 0 && a.height < vo::kMinVoHeight)
    throw cli::UsageError("--height: the vo engine tracks 2-D features and needs " + std::to_string(vo::kMinVoHeight) +
                          " rows or more, not '" + std::to_string(a.height) + "'");
  // Outputs that cannot be written are refused before the run, not after it.
  auto check_output = [](const std::string& path, const char* what, const char* option) {
    if (const std::string why = why_not_writable(path, what); !why.empty())
      throw std::runtime_error(shown_path(path) + " (" + option + "): " + why);
  };
  if (a.output != "-" && !a.output.empty()) check_output(a.output, "CSV file", "-o");
  // '--plot -' is standard output, as '-o -' is; it cannot take both.
  const bool plot_to_stdout = a.plot == "-";
  if (plot_to_stdout && (a.output == "-" || a.output.empty()))
    throw cli::UsageError("- (--plot): standard output takes the CSV already (no -o, or -o -): give -o FILE for "
                          "the CSV, or --plot FILE.svg");
  if (!a.hid_config.empty()) {
    check_output(a.hid_config, "configuration file", "--hid-config");
    // It is read back too: a FIFO or a device there would block or never end.
    if (path_present(a.hid_config))
      if (const std::string why = why_not_a_file(a.hid_config, "configuration file"); !why.empty())
        throw std::runtime_error(shown_path(a.hid_config) + " (--hid-config): " + why);
  }
  if (a.hid.rfind("file:", 0) == 0) check_output(a.hid.substr(5), "report file", "--hid file:");
  const Recording rec = load_recording(a.rec);
  if ((!rec.groundtruth.empty() || !a.plot.empty()) && !plot_to_stdout)
    check_output(a.plot.empty() ? default_plot_path(a) : a.plot, "plot file", a.plot.empty() ? "the plot" : "--plot");
  // No output may land on what the run reads, nor two outputs on one file.
  {
    std::vector<std::pair<std::string, const char*>> outs;
    // Standard output redirected to a file is an output too: 'run rec >
    // rec_estimates.svg' (the default plot's name) or '--hid file:x > x'
    // streamed the CSV there, then the other output was renamed over it, the
    // CSV lost, exit 0 ('>> rec/mav0/imu0/data.csv' appended it to the
    // recording).
    const bool csv_to_stdout = a.output == "-" || a.output.empty();
    if (const std::string so = standard_output_file(); !so.empty() && (csv_to_stdout || plot_to_stdout))
      outs.emplace_back(so, csv_to_stdout ? "standard output (the CSV)" : "standard output (the plot)");
    if (!csv_to_stdout) outs.emplace_back(a.output, "-o");
    if ((!rec.groundtruth.empty() || !a.plot.empty()) && !plot_to_stdout)
      outs.emplace_back(a.plot.empty() ? default_plot_path(a) : a.plot, a.plot.empty() ? "the plot" : "--plot");
    if (a.hid.rfind("file:", 0) == 0) outs.emplace_back(a.hid.substr(5), "--hid file:");
    if (!a.hid_config.empty()) outs.emplace_back(a.hid_config, "--hid-config");
    namespace fs = std::filesystem;
    for (size_t i = 0; i < outs.size(); ++i) {
      if (overwrites_recording(rec, outs[i].first))
        throw cli::UsageError(shown_path(outs[i].first) + " (" + outs[i].second +
                              "): that is part of the recording being read (" + shown_path(rec.root) +
                              "); write outputs elsewhere");
      // (devices and FIFOs, such as /dev/null, may take several outputs)
      // A symbolic link to nothing is written through (written_path): '--plot
      // lnk.svg' with lnk.svg -> est.csv, '-o est.csv' not yet written, ran,
      // exit 0, 'plot: lnk.svg' said and the plot replaced by the CSV.
      std::error_code e1;
      const fs::file_status st = fs::status(outs[i].first, e1);
      if (fs::exists(st) && !fs::is_regular_file(st)) continue;
      const std::string at = written_path(outs[i].first);
      for (size_t j = 0; j < i; ++j)
        if (!at.empty() && at == written_path(outs[j].first))
          throw cli::UsageError(shown_path(outs[i].first) + ": " + outs[j].second + " and " + outs[i].second +
                                " name the same file");
    }
  }
  // The plot is an SVG drawing: under another extension (plot.png) a viewer
  // would read it as what it is not; a name without one is taken as given.
  if (const std::string ext = std::filesystem::path(a.plot).extension().string(); !ext.empty()) {
    std::string lower = ext;
    for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (lower != ".svg")
      throw std::runtime_error(shown_path(a.plot) + " (--plot): the plot is an SVG drawing, not " + ext +
                               ": give a name ending in .svg (rsvg-convert -o PLOT.png PLOT.svg makes a PNG of it)");
  }
  const WorkingSize fallback = default_working_size(rec);
  options.size = {a.width > 0 ? a.width : fallback.width, a.height > 0 ? a.height : fallback.height};
  // As given: derive_settings takes a line scan's height to 1 (was: --height 2 run at height 1, silently).
  check_bins_down(rec, options.size, "--width/--height");
  options.ignore_distortion = a.ignore_distortion;
  options.lens_by_columns = a.lens_columns;
  options.gyro_offset_learning = !a.no_gyro_offset_learning;
  options.photometric_balance = a.photometric_balance;
  options.photometric_match = !a.no_photometric_match;
  options.elevation_band = a.elevation_band      ? RunOptions::Band::kOn
                           : a.no_elevation_band ? RunOptions::Band::kOff
                                                 : RunOptions::Band::kByView;
  options.clip_match = !a.no_clip_match;

  std::unique_ptr<HidSender> hid;
  if (!a.hid.empty()) {
    std::unique_ptr<hal::ConfigStore> store;
    if (!a.hid_config.empty()) {
      store = std::make_unique<FileConfigStore>(a.hid_config);
      // A device keeps its defaults when its stored configuration is invalid;
      // on the host that file is the user's, and a set would write the store
      // over it (a KEY=VALUE rig.cfg given here by mistake): refused.
      if (path_present(a.hid_config)) {
        uint8_t buf[protocol::kMaxStoredConfigSize];
        const size_t n = store->load(buf, sizeof buf);
        protocol::DeviceConfig c{};
        protocol::LensTables lens{};
        const protocol::ConfigField f =
            n == 0 ? protocol::ConfigField::kOk : protocol::decode_stored_config(buf, n, c, lens);
        const std::string not_a_store =
            ": --hid-config is the simulated device's own store, which a set overwrites: give a new name, or a file "
            "an earlier run saved there (a KEY=VALUE file is sent with lumavel-read config set --file)";
        if (n == 0 && std::filesystem::file_size(a.hid_config) > 0)
          throw std::runtime_error(shown_path(a.hid_config) + " (--hid-config): is " +
                                   std::to_string(std::filesystem::file_size(a.hid_config)) +
                                   " bytes, larger than a stored configuration (" + std::to_string(sizeof buf) +
                                   " B)" + not_a_store);
        // Bytes that frame no configuration were said in a report's words
        // ('malformed report: the report was malformed'), of a file.
        if (f == protocol::ConfigField::kMalformed)
          throw std::runtime_error(shown_path(a.hid_config) + " (--hid-config): is not a stored configuration (its " +
                                   std::to_string(n) + " bytes do not hold one: a stored configuration is the "
                                   "configuration report, its id, version and CRC checked, then the lens tables it "
                                   "names)" + not_a_store);
        if (f != protocol::ConfigField::kOk)
          throw std::runtime_error(shown_path(a.hid_config) + " (--hid-config): is not a stored configuration (" +
                                   protocol::to_string(f) + ": " + protocol::rule_of(f) + ")" + not_a_store);
      }
    }
    HidSenderOptions hid_options = hid_sender_options_for(a.hid);
    if (a.hid_wait_ms >= 0) hid_options.wait_ms = a.hid_wait_ms;
    hid = std::make_unique<HidSender>(open_host_link(a.hid), hid_options, std::move(store));
    const EstimatorSettings settings = run_settings(rec, options);
    hid->set_resolution(static_cast<uint16_t>(settings.width), static_cast<uint16_t>(settings.height));
    options.sink = [&hid](const EngineEstimate& e) { hid->send(e.t_ns, e.v, e.distance, e.heading, e.status, e.gyro_offset); };
  }

  EngineEstimate last{};  // for the summary
  options.sink = [&last, hid_sink = options.sink](const EngineEstimate& e) {
    last = e;
    if (hid_sink) hid_sink(e);
  };

  OutputFile out(a.output == "-" ? std::string() : a.output, "the CSV");
  // The plot is opened before the run (a folder that does not exist fails
  // now, not after it) and both outputs are committed together: never a CSV
  // without the plot that was asked for.
  const std::string plot = a.plot.empty() ? default_plot_path(a) : a.plot;
  const bool want_plot = !rec.groundtruth.empty() || !a.plot.empty();
  std::unique_ptr<OutputFile> plot_out;
  if (want_plot) plot_out = std::make_unique<OutputFile>(plot_to_stdout ? std::string() : plot, "the plot");

  std::unique_ptr<cli::Progress> bar;
  if (!a.quiet) bar = std::make_unique<cli::Progress>(static_cast<long>(rec.frames.size()), "run");
  auto progress = [&bar](size_t done, size_t) { bar->update(static_cast<long>(done)); };
  RunResult result;
  try {
    result = run_recording(rec, options, out.get(), bar ? progress : std::function<void(size_t, size_t)>{});
  } catch (...) {
    if (bar) bar->finish();
    throw;
  }
  if (bar) bar->finish();
  // Said even with -q: a warning about the input, not a part of the summary.
  if (rec.gyro_glitches > 0) std::fprintf(stderr, "run: warning: %s\n", rec.gyro_glitch_text.c_str());
  if (rec.frame_glitches > 0) std::fprintf(stderr, "run: warning: %s\n", rec.frame_glitch_text.c_str());
  for (int c = 0; c < 2; ++c)
    if (result.repeated[c] > 0) {
      const FramePairEntry& f = rec.frames[result.first_repeated[c]];
      std::fprintf(stderr,
                   "run: warning: cam%d repeated the frame before on %zu frame pair%s, the first %s (t = %llu ns), "
                   "while cam%d's moved on: %s skipped as dropped (a repeated frame reads as that camera standing "
                   "still)\n",
                   c, result.repeated[c], result.repeated[c] == 1 ? "" : "s", shown_path(f.path[c]).c_str(),
                   static_cast<unsigned long long>(f.t_ns), 1 - c, result.repeated[c] == 1 ? "it was" : "they were");
    }
  if (result.mirrored)
    std::fprintf(stderr, "run: warning: %s. The estimates are not to be trusted\n",
                 opposite_motion_text(result.motion_opposite, result.motion_same + result.motion_opposite, rec.root)
                     .c_str());
  if (const double d = focal_length_mismatch(rec); d >= kFocalMismatchWarn) {
    auto at = [&](int c) {
      const std::string f = rec.root + "/" + layout::kCamDir[c] + "/sensor.yaml";
      return rec.cam[c].line.intrinsics > 0 ? f + ":" + std::to_string(rec.cam[c].line.intrinsics) : f;
    };
    std::fprintf(stderr,
                 "run: warning: cam1's focal lengths differ from cam0's by %.1f %% (fu %g / %g px, fv %g / %g px: "
                 "%s and %s): lumavel reads both cameras' column sums as views of the same rows of the scene, and a "
                 "difference in focal length reads as motion (measured on a photo wall at 40x30: 0.6 %% gave E 4.6 %%, "
                 "2.2 %% gave 12 %%, against 1.0 %% with twin cameras), flagged by nothing. The estimates are not to "
                 "be trusted\n",
                 100 * d, rec.cam[1].fu, rec.cam[0].fu, rec.cam[1].fv, rec.cam[0].fv, at(0).c_str(), at(1).c_str());
  }
  if (result.still_camera >= 0)
    std::fprintf(stderr, "run: warning: %s. The estimates are not to be trusted\n",
                 still_camera_text(result.still_camera, result.motion_alone, result.motion_counted, rec.root).c_str());
  if (plot_out) {
    const std::string svg = track_svg(result.track, recording_name(a.rec) + ": V_xb, " + engine_name(options.engine) +
                                                        " engine, " + std::to_string(result.width) + "x" +
                                                        std::to_string(result.height));
    plot_out->write(svg);
    // Both outputs checked before either is moved into place: a CSV that
    // could not be written left the plot behind as if the run had succeeded.
    out.check();
    plot_out->commit();
  }
  out.commit();
  if (!a.quiet) {
    const double span = rec.frames.size() > 1
                            ? static_cast<double>(rec.frames.back().t_ns - rec.frames.front().t_ns) * 1e-9
                            : 0.0;
    std::fprintf(stderr, "%s: %zu frame pairs over %.3f s, %s engine, %dx%d working%s, %.0f frames/s (engine %.1f us/frame)\n",
                 shown_path(recording_name(a.rec)).c_str(), result.frames, span, engine_name(options.engine),
                 result.width, result.height, working_size_origin(a, rec).c_str(),
                 result.wall_s > 0 ? static_cast<double>(result.frames) / result.wall_s : 0.0,
                 result.frames ? 1e6 * result.step_s / static_cast<double>(result.frames) : 0.0);
    std::fprintf(stderr, "gaps: %s\n", format_gaps(rec.gaps).c_str());
    std::fprintf(stderr, "%s\n", format_flag_counts(count_flags(result.track)).c_str());
    if (result.lens_distorted || a.ignore_distortion || a.lens_columns)
      std::fprintf(stderr, "%s\n", lens_line(result.lens_distorted, a.ignore_distortion, a.lens_columns));
    // Say which rows the columns summed where it is not the narrow view's default.
    const double band_from_deg = config::kElevationBandMinHfovRad / config::kDeg;
    if (result.elevation_band || result.hfov_deg >= band_from_deg)
      std::fprintf(stderr, "columns: %s (hfov %.0f deg; the band is the default from %.0f)\n",
                   result.elevation_band ? "one elevation band (the rows every column sees)"
                                         : "all rows, edge rows correcting the turn (--no-elevation-band)",
                   result.hfov_deg, band_from_deg);
    if (result.pinhole_outside_px > 0)
      std::fprintf(stderr,
                   "lens: warning: %d pixels of the two cameras' pinhole views (%d each at the sensor's size) look "
                   "outside the sensor (a pincushion lens): they repeat the nearest edge pixel\n",
                   result.pinhole_outside_px, rec.cam[0].width * rec.cam[0].height);
    if (result.has_truth) std::fprintf(stderr, "%s\n", format_metrics(compute_metrics(result.track)).c_str());
    else std::fprintf(stderr, "no ground truth (state_groundtruth_estimate0/data.csv): no error figures\n");
    std::fprintf(stderr, "%s\n", gyro_offset_line(options.engine, !a.no_gyro_offset_learning, result.track, last.gyro_offset).c_str());
    std::fprintf(stderr, "%s\n", photometric_line(options.engine, !a.no_photometric_match, last.photometric).c_str());
    std::fprintf(stderr, "%s\n", clip_line(options, result).c_str());
    // The names as every message shows them (was: a recording folder named
    // 'e<ESC>[2Jrec' cleared the terminal with the summary's first line).
    if (want_plot) std::fprintf(stderr, "plot: %s\n", plot_to_stdout ? "standard output" : shown_path(plot).c_str());
    if (hid)
      std::fprintf(stderr, "hid: %u reports sent through %s, %u overruns\n", hid->sent(), shown_path(a.hid).c_str(),
                   hid->overruns());
    if (hid && a.hid_linger_s != 0) {
      if (a.hid_linger_s < 0) std::fprintf(stderr, "hid: answering feature reports until interrupted\n");
      else std::fprintf(stderr, "hid: answering feature reports for %g s\n", a.hid_linger_s);
    }
  }
  if (hid && a.hid_linger_s != 0) linger(*hid, a.hid_linger_s);
  return 0;
}

}  // namespace

void add_run_command(cli::Tool& tool) {
  auto a = std::make_shared<RunArgs>();
  CLI::App* c = tool.command("run", kRunDescription, [a] { return run(*a); });
  c->add_option("REC", a->rec, "the recording folder (REC or REC/mav0)")->required()->type_name("")->check(cli::path_name());
  c->add_option("--engine", a->engine,
                "estimator engine: the firmware's fixed-point core (default),\n"
                "the double-precision reference, or vo: a conventional\n"
                "keypoint stereo visual odometry (OpenCV KLT, triangulation,\n"
                "gyro-fixed rotation, RANSAC) for comparison, on the same\n"
                "binned frames; it learns no gyro offset, and its 'texture'\n"
                "column is the number of tracks that agreed on the motion")
      ->type_name("fixed|float|vo")
      ->check(engine_kind());
  c->add_option("-o,--output", a->output, "write the CSV to FILE instead of standard output ('-')")
      ->type_name("FILE")
      ->check(cli::path_name());
  c->add_option("--width", a->width,
                "working resolution width, " + std::to_string(kMinWorkWidth) + ".." +
                    std::to_string(kMaxWorkWidth) + " (default " + std::to_string(kDefaultColumns) +
                    ", or the\nsensor's width when smaller); the vo engine also runs\nunbinned at the sensor's own size, up to " +
                    std::to_string(kMaxVoWorkSize) + " (e.g. --width 240\n--height 180 on a 240x180 sensor)")
      ->type_name("W")
      ->check(cli::whole_number_in(kMinWorkWidth, kMaxVoWorkSize,
                                     " (above " + std::to_string(kMaxWorkWidth) + " only with --engine vo)"));
  c->add_option("--height", a->height,
                "working resolution height, 1.." + std::to_string(kMaxWorkHeight) + " (default " +
                    std::to_string(kDefaultRows) + ", or the\nsensor's height when smaller; 1 for line-scan input;\nthe vo engine needs " +
                    std::to_string(vo::kMinVoHeight) + " or more, up to " +
                    std::to_string(kMaxVoWorkSize) + ")")
      ->type_name("H")
      ->check(cli::whole_number_in(1, kMaxVoWorkSize,
                                     " (above " + std::to_string(kMaxWorkHeight) + " only with --engine vo)"));
  c->add_flag("--ignore-distortion", a->ignore_distortion,
              "estimate as if the lenses were pinhole, ignoring the\n"
              "distortion_model and coefficients of sensor.yaml (by\n"
              "default each frame is undistorted onto the pinhole of\n"
              "its intrinsics); for comparisons or doubtful calibrations");
  c->add_flag("--lens-columns", a->lens_columns,
              "correct the lens by per-column tables only, the frames\n"
              "binned as they are: what a device does with the lens\n"
              "tables lumavel-read config set sends (weaker on wide\n"
              "lenses turning; for comparisons)")
      ->excludes("--ignore-distortion");
  c->add_flag("--no-gyro-offset-learning", a->no_gyro_offset_learning,
              "take the gyro as it reads: do not learn its zero-rate\n"
              "offset while the images show the rig standing still\n"
              "(learned by default); for comparisons");
  c->add_flag("--no-photometric-match", a->no_photometric_match,
              "take the two cameras as photometric twins: do not learn\n"
              "cam1's black level and vignetting against cam0's (learned\n"
              "by default where one camera stands where the other stood:\n"
              "docs/design.md); for comparisons");
  c->add_flag("--no-clip-match", a->no_clip_match,
              "bin the frames as the cameras clipped them: do not clamp\n"
              "the camera that clips less where the other clips (done by\n"
              "default on the sensor's pixels: docs/design.md); for\n"
              "comparisons");
  c->add_flag("--photometric-balance", a->photometric_balance,
              "learn cam1's offset against cam0 per kernel over the\n"
              "first 4 m of travel and correct it (for cameras that are\n"
              "not photometric twins; experimental, off by default:\n"
              "docs/design.md)");
  auto* band_on = c->add_flag("--elevation-band", a->elevation_band,
                              "every column sums only the elevation band that all\n"
                              "columns see, so that turning wide cameras do not read\n"
                              "as motion (the default from a horizontal field of view\n"
                              "of 80 degrees: docs/design.md)");
  c->add_flag("--no-elevation-band", a->no_elevation_band,
              "every column sums all rows, whatever the field of view\n"
              "(the turn's elevation reach corrected by the edge rows)")
      ->excludes(band_on);
  c->add_option("--plot", a->plot,
                "plot file (default: REC_estimates.svg next to the -o file,\n"
                "or in the current folder when the output is standard output\n"
                "or a device such as /dev/null; '-': standard output, with -o FILE);\n"
                "written when the recording has ground truth or when --plot is given")
      ->type_name("FILE.svg")
      ->check(cli::path_name());
  c->add_option("--hid", a->hid,
                                   "also send every estimate as a USB HID input report through\n"
                                   "SPEC: uhid, hidg:/dev/hidgN or file:PATH (docs/usb-hid.md)")
                         ->type_name("SPEC")
                         ->check(host_link_spec());
  c->add_option("--hid-config", a->hid_config,
                "with --hid: configuration sets from the host (lumavel-read\n"
                "config set) are validated, accepted and saved in FILE, and\n"
                "config get returns them, also in later runs; the running\n"
                "engine keeps the recording's configuration. Without it,\n"
                "sets are refused")
      ->type_name("FILE")
      ->check(cli::path_name());
  c->add_option("--hid-wait-ms", a->hid_wait_ms,
                "with --hid: how long a report waits for the host to take it\n"
                "before it is dropped and counted as an overrun, 0..600000\n"
                "(default 20; large values make the stream lossless with a\n"
                "slow host)")
      ->type_name("N")
      ->check(cli::whole_number_in(0, 600000));
  c->add_option("--hid-linger", a->hid_linger_s,
                "with --hid: after the last estimate keep the device and\n"
                "answer feature reports (info, config) for S seconds (up to 1e9);\n"
                "-1 until interrupted (SIGINT/SIGTERM, exit 0); default 0")
      ->type_name("S")
      ->check(linger_seconds());
  c->add_flag("-q,--quiet", a->quiet, "no progress and no summary on standard error");
}

}  // namespace lumavel::host
