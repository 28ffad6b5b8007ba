// Command line of `lumavel-sim render`.
#include "lumavel/host/render_command.hpp"

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <string>

#include "lumavel/host/render/photometric_presets.hpp"
#include "lumavel/host/render/recording_renderer.hpp"
#include "lumavel/host/render/scenario_loader.hpp"

namespace lumavel::host {
namespace {

const char* const kHelpTop =
    "Usage: lumavel-sim render SCENARIO.yaml OUT [options]\n"
    "\n"
    "Renders a synthetic stereo camera + gyro recording from a scenario file into\n"
    "OUT/mav0/ in the EuRoC layout (cam0/, cam1/, imu0/, state_groundtruth_estimate0/),\n"
    "as specified by the recording-format contract. Scenario keys are documented in\n"
    "host_sim/scenarios/README.md.\n"
    "\n"
    "Options:\n"
    "  --resolution WxH  camera resolution (the field of view is kept), e.g. 40x30\n"
    "  --exposure F      exposure time as a fraction of the frame period (0 = instant)\n"
    "  --seed N          seed of pixel noise, fixed patterns, gyro noise and frame drops\n"
    "  --duration S      length in seconds (the last segment continues if longer)\n"
    "  --camera-mismatch NAME\n"
    "                    photometric preset for cam0 and cam1, replacing the\n"
    "                    scenario's photometric block (presets below)\n"
    "  --threads N       worker threads (default 2)\n"
    "  --force           replace an existing OUT/mav0\n"
    "  --quiet           no progress bar and no summary\n"
    "  -h, --help        this text\n"
    "\n";

const char* const kHelpBottom =
    "\n"
    "Exit status: 0 done, 1 bad scenario or write error (message names the file and\n"
    "line), 2 bad usage.\n";

int usage_error(const std::string& what) {
  std::fprintf(stderr, "lumavel-sim render: %s\n(see lumavel-sim render --help)\n", what.c_str());
  return 2;
}

bool parse_number(const char* text, double& out) {
  char* end = nullptr;
  out = std::strtod(text, &end);
  return end != text && *end == '\0';
}

}  // namespace

int render_main(int argc, char** argv) {
  std::string scenario_path, out_dir;
  render::Overrides ov;
  render::RenderOptions opt;
  bool force = false, quiet = false;
  for (int k = 1; k < argc; ++k) {
    const std::string a = argv[k];
    auto value = [&]() -> const char* { return k + 1 < argc ? argv[++k] : nullptr; };
    if (a == "-h" || a == "--help") {
      std::fputs(kHelpTop, stdout);
      std::fputs("Photometric presets:\n", stdout);
      for (const auto& p : render::photometric_presets())
        std::printf("  %-16s %s\n", p.name, p.what);
      std::fputs(kHelpBottom, stdout);
      return 0;
    } else if (a == "--resolution") {
      const char* v = value();
      int w = 0, h = 0;
      char extra = 0;
      if (!v || std::sscanf(v, "%dx%d%c", &w, &h, &extra) != 2 || w < 1 || h < 1 || w > 8192 || h > 8192)
        return usage_error("--resolution needs WxH, e.g. 640x480");
      ov.width = w;
      ov.height = h;
    } else if (a == "--exposure") {
      const char* v = value();
      double e = 0;
      if (!v || !parse_number(v, e) || e < 0 || e > 10)
        return usage_error("--exposure needs a fraction of the frame period in [0, 10]");
      ov.exposure_frames = e;
    } else if (a == "--seed") {
      const char* v = value();
      double sd = 0;
      if (!v || !parse_number(v, sd) || sd < 0 || sd != static_cast<double>(static_cast<long long>(sd)))
        return usage_error("--seed needs a whole number >= 0");
      ov.seed = static_cast<long long>(sd);
    } else if (a == "--duration") {
      const char* v = value();
      double d = 0;
      if (!v || !parse_number(v, d) || d <= 0 || d > 1e6) return usage_error("--duration needs seconds > 0");
      ov.duration_s = d;
    } else if (a == "--camera-mismatch") {
      const char* v = value();
      if (!v || !render::find_photometric_preset(v))
        return usage_error("--camera-mismatch needs one of: " + render::photometric_preset_names());
      ov.camera_mismatch = v;
    } else if (a == "--threads") {
      const char* v = value();
      double n = 0;
      if (!v || !parse_number(v, n) || n < 1 || n > 256) return usage_error("--threads needs 1..256");
      opt.threads = static_cast<int>(n);
    } else if (a == "--force") {
      force = true;
    } else if (a == "--quiet") {
      quiet = true;
    } else if (!a.empty() && a[0] == '-') {
      return usage_error("unknown option " + a);
    } else if (scenario_path.empty()) {
      scenario_path = a;
    } else if (out_dir.empty()) {
      out_dir = a;
    } else {
      return usage_error("unexpected argument " + a);
    }
  }
  if (scenario_path.empty() || out_dir.empty()) return usage_error("needs SCENARIO.yaml and OUT");
  opt.progress = !quiet;

  try {
    render::Scenario s = render::load_scenario(scenario_path);
    render::apply_overrides(s, ov);
    const std::string mav0 = out_dir + "/mav0";
    if (std::filesystem::exists(mav0)) {
      if (!force) {
        std::fprintf(stderr, "lumavel-sim render: %s already exists (use --force to replace it)\n",
                     mav0.c_str());
        return 1;
      }
      std::filesystem::remove_all(mav0);
    }
    const render::RenderSummary r = render::render_recording(s, out_dir, opt);
    if (!quiet) {
      std::string bg = "no background visible";
      if (r.max_background_frame >= 0) {
        char buf[96];
        std::snprintf(buf, sizeof buf, "background up to %.1f%% of an image (frame %d)",
                      100 * r.max_background, r.max_background_frame);
        bg = buf;
      }
      std::printf(
          "%s: %d frame pairs (%d dropped) %dx%d, %zu gyro samples, %zu ground-truth samples, "
          "max %d sub-frames, %s, %.1f s\n",
          mav0.c_str(), r.frames - r.dropped, r.dropped, s.camera.width, s.camera.height,
          r.imu_samples, r.groundtruth_samples, r.max_subframes, bg.c_str(), r.seconds);
    }
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "lumavel-sim render: %s\n", e.what());
    return 1;
  }
}

}  // namespace lumavel::host
