#include "run_command.hpp"

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "cli_args.hpp"
#include "lumavel/core/status.hpp"
#include "output_file.hpp"
#include "lumavel/host/file_config_store.hpp"
#include "lumavel/host/hid_link.hpp"
#include "lumavel/host/hid_sender.hpp"
#include "lumavel/host/run_recording.hpp"
#include "lumavel/host/track_plot.hpp"

namespace lumavel::host {
namespace {

const char* const kRunHelp =
    "usage: lumavel-sim run REC [options]\n"
    "\n"
    "Runs the estimator over the recording REC (EuRoC/ASL layout, REC or REC/mav0)\n"
    "and writes the estimates CSV (docs/estimates-csv.md): one row per frame pair,\n"
    "  timestamp_ns,v_xb_mps,distance_m,heading_rad,status,gyro_offset_radps,v_direct_mps,texture\n"
    "\n"
    "options:\n"
    "  --engine fixed|float|vo\n"
    "                         estimator engine: the firmware's fixed-point core (default),\n"
    "                         the double-precision reference, or vo: a conventional\n"
    "                         keypoint stereo visual odometry (OpenCV KLT, triangulation,\n"
    "                         gyro-fixed rotation, RANSAC) for comparison, on the same\n"
    "                         binned frames; it learns no gyro offset, and its 'texture'\n"
    "                         column is the number of tracks that agreed on the motion\n"
    "  -o, --output FILE      write the CSV to FILE instead of standard output ('-')\n"
    "  --width W              working resolution width, 16..160 (default 40); the vo engine\n"
    "                         also runs unbinned at the sensor's own resolution (e.g.\n"
    "                         --width 240 --height 180 on a 240x180 sensor)\n"
    "  --height H             working resolution height, 1..128 (default 30; 1 for line-scan input);\n"
    "                         the vo engine needs 12 or more (it refuses line-scan input)\n"
    "  --ignore-distortion    estimate as if the lenses were pinhole, ignoring the\n"
    "                         distortion_model and coefficients of sensor.yaml (by\n"
    "                         default the column angles come from the undistorted\n"
    "                         geometry); for comparisons or doubtful calibrations\n"
    "  --no-gyro-offset-learning\n"
    "                         take the gyro as it reads: do not learn its zero-rate\n"
    "                         offset while the images show the rig standing still\n"
    "                         (learned by default); for comparisons\n"
    "  --plot FILE.svg        plot file (default: REC_estimates.svg next to the -o file,\n"
    "                         or in the current folder); written when the recording has\n"
    "                         ground truth or when --plot is given\n"
    "  --hid SPEC             also send every estimate as a USB HID input report through\n"
    "                         SPEC: uhid, hidg:/dev/hidgN or file:PATH (docs/usb-hid.md)\n"
    "  --hid-config FILE      with --hid: configuration sets from the host (lumavel-read\n"
    "                         config set) are validated, accepted and saved in FILE, and\n"
    "                         config get returns them, also in later runs; the running\n"
    "                         engine keeps the recording's configuration. Without it,\n"
    "                         sets are refused\n"
    "  --hid-wait-ms N        with --hid: how long a report waits for the host to take it\n"
    "                         before it is dropped and counted as an overrun (default 20;\n"
    "                         large values make the stream lossless with a slow host)\n"
    "  --hid-linger S         with --hid: after the last estimate keep the device and\n"
    "                         answer feature reports (info, config) for S seconds;\n"
    "                         -1 until interrupted (SIGINT/SIGTERM, exit 0); default 0\n"
    "  --quiet                no progress and no summary on standard error\n"
    "  -h, --help             this help\n"
    "\n"
    "A summary goes to standard error: frames, gaps, whether the lens distortion was\n"
    "corrected or ignored (when sensor.yaml has one or --ignore-distortion is given) and,\n"
    "with ground truth (state_groundtruth_estimate0), the paper's error E (eq. 22), L1\n"
    "and RMS errors, worst and mean error after the first second; last, the gyro\n"
    "zero-rate offset learned at standstill (or why none was).\n"
    "\n"
    "exit status: 0 done, 1 bad recording or failure (the message names the file and\n"
    "line or frame), 2 usage error\n";

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
  WorkingSize size;
  bool quiet = false;
  bool help = false;
  bool ignore_distortion = false;
  bool gyro_offset_learning = true;
};

RunArgs parse(int argc, char** argv) {
  RunArgs a;
  std::string v;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "-h" || arg == "--help") {
      a.help = true;
    } else if (arg == "--quiet" || arg == "-q") {
      a.quiet = true;
    } else if (arg == "--ignore-distortion") {
      a.ignore_distortion = true;
    } else if (arg == "--no-gyro-offset-learning") {
      a.gyro_offset_learning = false;
    } else if (option_value(argc, argv, i, "--engine", v)) {
      if (v != "fixed" && v != "float" && v != "vo")
        throw UsageError("--engine must be 'fixed', 'float' or 'vo', not '" + v + "'");
      a.engine = v;
    } else if (option_value(argc, argv, i, "-o", v) || option_value(argc, argv, i, "--output", v)) {
      a.output = v == "-" ? std::string() : v;  // "-": standard output
    } else if (option_value(argc, argv, i, "--plot", v)) {
      a.plot = v;
    } else if (option_value(argc, argv, i, "--hid", v)) {
      a.hid = v;
    } else if (option_value(argc, argv, i, "--hid-config", v)) {
      if (v.empty()) throw UsageError("--hid-config needs a file name");
      a.hid_config = v;
    } else if (option_value(argc, argv, i, "--hid-wait-ms", v)) {
      a.hid_wait_ms = parse_int(v, "--hid-wait-ms");
      if (a.hid_wait_ms < 0 || a.hid_wait_ms > 600000) throw UsageError("--hid-wait-ms must be in 0..600000");
    } else if (option_value(argc, argv, i, "--hid-linger", v)) {
      char* end = nullptr;
      a.hid_linger_s = std::strtod(v.c_str(), &end);
      if (v.empty() || *end != '\0' || !std::isfinite(a.hid_linger_s) || (a.hid_linger_s < 0 && a.hid_linger_s != -1))
        throw UsageError("--hid-linger must be a number of seconds >= 0, or -1, not '" + v + "'");
    } else if (option_value(argc, argv, i, "--width", v)) {
      a.size.width = parse_int(v, "--width");
    } else if (option_value(argc, argv, i, "--height", v)) {
      a.size.height = parse_int(v, "--height");
    } else if (!arg.empty() && arg[0] == '-') {
      throw UsageError("unknown option '" + arg + "'");
    } else if (a.rec.empty()) {
      a.rec = arg;
    } else {
      throw UsageError("unexpected argument '" + arg + "' (one recording per run)");
    }
  }
  if (a.help) return a;
  if (a.rec.empty()) throw UsageError("missing the recording folder REC");
  if (a.hid.empty() && (!a.hid_config.empty() || a.hid_linger_s != 0 || a.hid_wait_ms >= 0))
    throw UsageError("--hid-config, --hid-wait-ms and --hid-linger need --hid SPEC");
  if (a.engine == "vo") {
    // The sensors' sizes bound it when the recording is read.
    if (a.size.width < kMinWorkWidth || a.size.width > kMaxVoWorkSize)
      throw UsageError("--width must be in " + std::to_string(kMinWorkWidth) + ".." + std::to_string(kMaxVoWorkSize) +
                       " with --engine vo");
    if (a.size.height < 1 || a.size.height > kMaxVoWorkSize)
      throw UsageError("--height must be in 1.." + std::to_string(kMaxVoWorkSize) + " with --engine vo");
    return a;
  }
  if (a.size.width < kMinWorkWidth || a.size.width > kMaxWorkWidth)
    throw UsageError("--width must be in " + std::to_string(kMinWorkWidth) + ".." + std::to_string(kMaxWorkWidth) +
                     (a.size.width > kMaxWorkWidth ? " (the firmware core's limit; --engine vo goes up to the sensor's width)"
                                                   : ""));
  if (a.size.height < 1 || a.size.height > kMaxWorkHeight)
    throw UsageError("--height must be in 1.." + std::to_string(kMaxWorkHeight));
  return a;
}

// "path/to/REC/" or "path/to/REC/mav0" -> "REC".
std::string recording_name(std::string path) {
  while (path.size() > 1 && path.back() == '/') path.pop_back();
  auto base = [](const std::string& p) {
    const size_t s = p.find_last_of('/');
    return s == std::string::npos ? p : p.substr(s + 1);
  };
  std::string name = base(path);
  if (name == "mav0") {
    const size_t s = path.find_last_of('/');
    if (s != std::string::npos && s > 0) name = base(path.substr(0, s));
  }
  return name.empty() || name == "." || name == ".." ? std::string("recording") : name;
}

std::string default_plot_path(const RunArgs& a) {
  std::string dir;
  const size_t s = a.output.find_last_of('/');
  if (s != std::string::npos) dir = a.output.substr(0, s + 1);
  return dir + recording_name(a.rec) + "_estimates.svg";
}

std::string gaps_line(const Recording& rec) {
  char buf[256];
  std::snprintf(buf, sizeof buf,
                "gaps: %d frame gaps (about %ld pairs missing, longest %.3f s), %d gyro holes (longest %.3f s)",
                rec.gaps.frame_gaps, rec.gaps.frames_missing, rec.gaps.longest_frame_gap_s, rec.gaps.gyro_holes,
                rec.gaps.longest_gyro_hole_s);
  return buf;
}

const char* lens_line(bool distorted, bool ignored) {
  if (!distorted) return "lens: no distortion in sensor.yaml (--ignore-distortion changes nothing)";
  return ignored ? "lens: distortion IGNORED (--ignore-distortion): columns read as pinhole"
                 : "lens: radial-tangential distortion corrected (column angles from sensor.yaml)";
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
  const Recording rec = load_recording(a.rec);
  RunOptions options;
  options.engine = parse_engine_kind(a.engine);
  options.size = a.size;
  options.ignore_distortion = a.ignore_distortion;
  options.gyro_offset_learning = a.gyro_offset_learning;

  std::unique_ptr<HidSender> hid;
  if (!a.hid.empty()) {
    std::unique_ptr<hal::ConfigStore> store;
    if (!a.hid_config.empty()) store = std::make_unique<FileConfigStore>(a.hid_config);
    HidSenderOptions hid_options = hid_sender_options_for(a.hid);
    if (a.hid_wait_ms >= 0) hid_options.wait_ms = a.hid_wait_ms;
    hid = std::make_unique<HidSender>(open_host_link(a.hid), hid_options, std::move(store));
    const EstimatorSettings settings = run_settings(rec, options);
    hid->set_resolution(static_cast<uint16_t>(settings.width), static_cast<uint16_t>(settings.height));
    options.sink = [&hid](const EngineEstimate& e) { hid->send(e.t_ns, e.v, e.distance, e.heading, e.status, e.gyro_offset); };
  }

  double last_offset = 0;  // for the summary
  options.sink = [&last_offset, hid_sink = options.sink](const EngineEstimate& e) {
    last_offset = e.gyro_offset;
    if (hid_sink) hid_sink(e);
  };

  OutputFile out(a.output);
  static char out_buf[1 << 16];
  if (out.get() == stdout) std::setvbuf(stdout, out_buf, _IOFBF, sizeof out_buf);

  const bool show_progress = !a.quiet && ::isatty(STDERR_FILENO);
  auto progress = [](size_t done, size_t total) {
    std::fprintf(stderr, "\rframe %zu/%zu", done, total);
    std::fflush(stderr);
  };
  RunResult result;
  try {
    result = run_recording(rec, options, out.get(), show_progress ? progress : std::function<void(size_t, size_t)>{});
    out.commit();
  } catch (...) {
    if (show_progress) std::fputc('\n', stderr);
    throw;
  }
  if (show_progress) std::fprintf(stderr, "\r%*s\r", 40, "");

  const std::string plot = a.plot.empty() ? default_plot_path(a) : a.plot;
  const bool want_plot = result.has_truth || !a.plot.empty();
  if (want_plot)
    write_track_svg(plot, result.track,
                    recording_name(a.rec) + ": V_xb, " + engine_name(options.engine) + " engine, " +
                        std::to_string(result.width) + "x" + std::to_string(result.height));
  if (!a.quiet) {
    const double span = rec.frames.size() > 1
                            ? static_cast<double>(rec.frames.back().t_ns - rec.frames.front().t_ns) * 1e-9
                            : 0.0;
    std::fprintf(stderr, "%s: %zu frame pairs over %.3f s, %s engine, %dx%d working, %.0f frames/s (engine %.1f us/frame)\n",
                 recording_name(a.rec).c_str(), result.frames, span, engine_name(options.engine),
                 result.width, result.height,
                 result.wall_s > 0 ? static_cast<double>(result.frames) / result.wall_s : 0.0,
                 result.frames ? 1e6 * result.step_s / static_cast<double>(result.frames) : 0.0);
    std::fprintf(stderr, "%s\n", gaps_line(rec).c_str());
    if (result.lens_distorted || a.ignore_distortion)
      std::fprintf(stderr, "%s\n", lens_line(result.lens_distorted, a.ignore_distortion));
    if (result.has_truth) std::fprintf(stderr, "%s\n", format_metrics(compute_metrics(result.track)).c_str());
    else std::fprintf(stderr, "no ground truth (state_groundtruth_estimate0/data.csv): no error figures\n");
    std::fprintf(stderr, "%s\n", gyro_offset_line(options.engine, a.gyro_offset_learning, result.track, last_offset).c_str());
    if (want_plot) std::fprintf(stderr, "plot: %s\n", plot.c_str());
    if (hid) std::fprintf(stderr, "hid: %u reports sent through %s, %u overruns\n", hid->sent(), a.hid.c_str(), hid->overruns());
    if (hid && a.hid_linger_s != 0) {
      if (a.hid_linger_s < 0) std::fprintf(stderr, "hid: answering feature reports until interrupted\n");
      else std::fprintf(stderr, "hid: answering feature reports for %g s\n", a.hid_linger_s);
    }
  }
  if (hid && a.hid_linger_s != 0) linger(*hid, a.hid_linger_s);
  return 0;
}

}  // namespace

int run_main(int argc, char** argv) {
  RunArgs args;
  try {
    args = parse(argc, argv);
  } catch (const UsageError& e) {
    std::fprintf(stderr, "lumavel-sim run: %s\n(see lumavel-sim run --help)\n", e.what());
    return 2;
  }
  if (args.help) {
    std::fputs(kRunHelp, stdout);
    return 0;
  }
  try {
    return run(args);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "lumavel-sim run: error: %s\n", e.what());
    return 1;
  }
}

}  // namespace lumavel::host
