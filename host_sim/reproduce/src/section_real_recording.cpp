// "Real recording: slider_depth": the Event-Camera Dataset's slider sequence
// (read from outside the project: its licence forbids copying it in), made
// into a stereo recording by time shift, run by both engines with and
// without the lens-distortion correction.
#include <cstdio>
#include <filesystem>
#include <sstream>

#include "lumavel/host/import_slider.hpp"
#include "lumavel/host/recording.hpp"
#include "lumavel/host/run_metrics.hpp"
#include "lumavel/host/run_recording.hpp"
#include "sections.hpp"

namespace lumavel::host::reproduce {
namespace fs = std::filesystem;

const char* const kRealRecordingTitle = "Real recording: slider_depth";

namespace {

RunMetrics run_once(const Recording& rec, EngineKind engine, WorkingSize size, bool ignore_distortion) {
  RunOptions ro;
  ro.engine = engine;
  ro.size = size;
  ro.ignore_distortion = ignore_distortion;
  return compute_metrics(run_recording(rec, ro, nullptr).track);
}

std::string fmt(const char* f, double a, double b = 0, double c = 0, double d = 0) {
  char buf[256];
  std::snprintf(buf, sizeof buf, f, a, b, c, d);
  return buf;
}

}  // namespace

Section real_recording_section(const SectionContext& ctx) {
  Section sec;
  sec.title = kRealRecordingTitle;
  std::ostringstream md;
  md << "\n## " << kRealRecordingTitle << "\n\n";
  if (!fs::is_directory(ctx.slider_data)) {
    md << "Skipped: `" << ctx.slider_data << "` is not there (the data is never copied into the project; "
       << "pass its folder with `--slider-data`).\n";
    sec.markdown = md.str();
    return sec;
  }
  md << "A DAVIS240C (240x180, ~26 Hz, barrel lens k1 = -0.139) on a linear slider past objects at 1-2 m "
        "(Mueggler et al., IJRR 2017; licence CC BY-NC-SA 3.0, read from `--slider-data`, never copied). One "
        "camera and no gyro: `lumavel-sim import-slider` makes cam1 by time shift (the frames bracketing the "
        "position h ahead, blended by position; docs/real-recording.md says how and what that costs). "
        "\"Corrected\" undistorts each frame onto the pinhole of sensor.yaml's intrinsics before binning (the "
        "default); \"ignored\" runs as if the lens were pinhole (`run --ignore-distortion`).\n\n"
        "Commands: `lumavel-sim import-slider DATA REC [--baseline H]`, then `lumavel-sim run REC [--engine "
        "float|vo] [--width 80 --height 60] [--ignore-distortion]`.\n\n";
  const std::string rec_dir = ctx.out + "/rec/slider_h002";
  fs::remove_all(rec_dir);
  std::fprintf(stderr, "[real] import %s\n", ctx.slider_data.c_str());
  ImportSliderOptions io;
  const ImportSliderSummary sum = import_slider(ctx.slider_data, rec_dir, io);
  const Recording rec = load_recording(rec_dir);
  md << fmt("h = %.3f m, ", io.baseline) << sum.pairs << " of " << sum.frames_in << " frames paired.\n\n"
     << "| engine | working | E corrected | E ignored | bias after 1 s, corrected | bias after 1 s, ignored |\n"
     << "|---|---|---|---|---|---|\n";
  for (WorkingSize size : {WorkingSize{40, 30}, WorkingSize{80, 60}}) {
    for (EngineKind kind : {EngineKind::kVo, EngineKind::kFixed, EngineKind::kFloat}) {
      const RunMetrics with = run_once(rec, kind, size, false), without = run_once(rec, kind, size, true);
      md << "| " << engine_name(kind) << " | " << size.width << "x" << size.height << " | "
         << fmt("%.2f %% | %.2f %% | %+.4f m/s | %+.4f m/s |\n", with.e_percent, without.e_percent, with.mean_after,
                without.mean_after);
    }
  }
  md << "\nBaseline sweep (corrected; VO: the keypoint stereo VO on the same frames). Target of issue 10: the "
        "fixed engine's E <= 2 % at every h, at 40x30 and at 80x60.\n\n"
        "| h | pairs | VO: E 40x30 | fixed: E 40x30 | fixed: bias after 1 s | VO: E 80x60 | fixed: E 80x60 |\n"
        "|---|---|---|---|---|---|---|\n";
  for (double h : {0.01, 0.02, 0.03, 0.04, 0.06, 0.08}) {
    const std::string dir = ctx.out + "/rec/slider_sweep";
    fs::remove_all(dir);
    ImportSliderOptions o;
    o.baseline = h;
    std::fprintf(stderr, "[real] sweep h = %.3f m\n", h);
    const ImportSliderSummary s = import_slider(ctx.slider_data, dir, o);
    const Recording sweep = load_recording(dir);
    const RunMetrics m = run_once(sweep, EngineKind::kFixed, {40, 30}, false);
    const RunMetrics m80 = run_once(sweep, EngineKind::kFixed, {80, 60}, false);
    const RunMetrics v = run_once(sweep, EngineKind::kVo, {40, 30}, false);
    const RunMetrics v80 = run_once(sweep, EngineKind::kVo, {80, 60}, false);
    md << fmt("| %.3f m | ", h) << s.pairs
       << fmt(" | %.2f %% | %.2f %% | %+.4f m/s | %.2f %% | ", v.e_percent, m.e_percent, m.mean_after, v80.e_percent)
       << fmt("%.2f %% |\n", m80.e_percent);
    if (h != 0.03) {  // issue 10's baselines
      sec.targets.push_back({fmt("slider_depth, h = %.0f cm, E at 40x30", 100 * h), "<= 2 %",
                             fmt("%.2f %%", m.e_percent), m.e_percent <= 2});
      sec.targets.push_back({fmt("slider_depth, h = %.0f cm, E at 80x60", 100 * h), "<= 2 %",
                             fmt("%.2f %%", m80.e_percent), m80.e_percent <= 2});
    }
  }
  md << "\nReading: the lens correction changes E by a few hundredths of a point here. Both cameras share the "
        "lens and the motion is a pure translation, where the column-angle error cancels between the temporal "
        "and the stereo differences; it matters for the rotation term (see the lens study above). The "
        "differential alone reads V low above h = 2 cm, faster than h grows: the near objects' disparity h/Z "
        "(0.02-0.08 rad) approaches the kernels' scales (0.057 and 0.086 rad at this 39 deg view). The time of "
        "flight (docs/design.md) does not depend on the depth and holds E near 2-3.5 % from 1 to 8 cm; what is "
        "left comes from the first frames (V starts at 0, about 1.3 points of E here) and from cam1 being a "
        "blend of two of cam0's frames (below one frame spacing, 1.2 cm, cam1 is mostly cam0's own frames).\n";
  sec.markdown = md.str();
  return sec;
}

}  // namespace lumavel::host::reproduce
