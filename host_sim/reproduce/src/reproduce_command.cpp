#include "lumavel/host/reproduce_command.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include "lumavel/core/status.hpp"
#include "lumavel/host/recording.hpp"
#include "lumavel/host/render/scenario_loader.hpp"
#include "lumavel/host/run_recording.hpp"
#include "lumavel/host/track_plot.hpp"
#include "render_cache.hpp"
#include "results_markdown.hpp"
#include "sections.hpp"
#include "studies.hpp"

#ifndef LUMAVEL_SOURCE_DIR
#define LUMAVEL_SOURCE_DIR "."
#endif

namespace lumavel::host {
namespace fs = std::filesystem;
using namespace reproduce;

namespace {

struct Options {
  bool quick = false;
  std::string out = "out/reproduce";
  std::string doc = "docs/results.md";
  std::string scenarios = std::string(LUMAVEL_SOURCE_DIR) + "/host_sim/scenarios";
  int threads = 2;
  std::string only;       // run only the studies whose title contains this
  std::string slider_data = std::string(LUMAVEL_SOURCE_DIR) + "/../shared/data/slider_depth";
  bool doc_given = false;
};

void usage(std::FILE* f) {
  std::fputs(
      "usage: lumavel-sim reproduce [--quick] [--only TEXT] [--out DIR] [--doc FILE] [--scenarios DIR] [--threads N]\n"
      "\n"
      "Renders the paper's studies (Section IV-B simulations, Table I resolutions,\n"
      "Table II exposures, the trolley, a turning run, untextured/dark/dropped\n"
      "frames, lens distortion, gyro offset), runs the fixed-point and the double-precision\n"
      "engines and the keypoint stereo VO baseline (--engine vo) on each and writes the\n"
      "paper's figures, the VO's and ours side by side to FILE,\n"
      "with plots in a folder next to it; then calibrates the misalignment of\n"
      "rendered rigs and runs the real slider_depth recording when its data is\n"
      "there. Renders are cached in DIR between runs.\n"
      "\n"
      "  --quick          a small subset (40x30 and below, short runs) for CI\n"
      "  --only TEXT      only the studies whose title contains TEXT (e.g. Lens); the\n"
      "                   page then goes to DIR/results.md unless --doc is given\n"
      "  --out DIR        recordings and plots (default out/reproduce)\n"
      "  --doc FILE       results page (default docs/results.md; plots in docs/results/)\n"
      "  --scenarios DIR  scenario folder (default the source tree's host_sim/scenarios)\n"
      "  --threads N      render threads (default 2)\n"
      "  --slider-data D  the slider_depth dataset (default ../shared/data/slider_depth next to\n"
      "                   the source tree; its section is skipped when it is missing)\n",
      f);
}

// Renders a case unless an identical render is already cached; adds the
// render time to *render_s, or counts the reuse in *reused.
std::string render_case(const Case& c, const Options& o, double* render_s, int* reused) {
  const LensVariant lens = lens_variant(c);
  const GyroVariant gyro = gyro_variant(c);  // its render_id is lens's for other cases
  const std::string dir = o.out + "/rec/" + gyro.render_id;
  std::ostringstream key;
  key << c.render_w << "x" << c.render_h << " e" << c.exposure << " d" << c.duration
      << (lens.no_lens ? " no-lens" : "") << (gyro.no_offset ? " no-gyro-offset" : "");
  const CachedRender r = render_cached(o.scenarios + "/" + c.scenario, dir, key.str(), [&](render::Scenario& s) {
    render::Overrides ov;
    ov.width = c.render_w;
    ov.height = c.render_h;
    ov.exposure_frames = c.exposure;
    ov.duration_s = c.duration;
    render::apply_overrides(s, ov);
    if (lens.no_lens) s.camera.distortion = {};  // same seed and motion, pinhole camera
    if (gyro.no_offset) s.imu.gyro_bias_z = 0;    // same seed, images and gyro noise
  }, o.threads);
  if (r.reused) {
    ++*reused;
  } else {
    std::fprintf(stderr, "    rendered %d frame pairs in %.1f s\n", r.frames, r.seconds);
    *render_s += r.seconds;
  }
  return dir;
}

// The paper's studies, the lens and the gyro offset studies, filtered by --only.
std::vector<Study> selected_studies(const Options& o) {
  std::vector<Study> all = paper_studies(o.quick), kept;
  all.push_back(lens_study(o.quick));
  all.push_back(gyro_offset_study(o.quick));
  for (const Study& st : all)
    if (st.title.find(o.only) != std::string::npos) kept.push_back(st);
  return kept;
}

// The sections after the studies (sections.hpp), filtered by --only.
std::vector<Section (*)(const SectionContext&)> selected_sections(const Options& o) {
  std::vector<Section (*)(const SectionContext&)> kept;
  if (std::string(kCalibrationTitle).find(o.only) != std::string::npos) kept.push_back(calibration_section);
  if (std::string(kRealRecordingTitle).find(o.only) != std::string::npos) kept.push_back(real_recording_section);
  return kept;
}

int run(const Options& o) {
  const auto t0 = std::chrono::steady_clock::now();
  const std::vector<Study> studies = selected_studies(o);
  const fs::path doc(o.doc);
  const fs::path plot_dir = doc.parent_path() / doc.stem();
  fs::create_directories(plot_dir);
  fs::create_directories(o.out);
  std::vector<StudyResult> results;
  double render_s = 0;
  int reused = 0;
  size_t n_cases = 0, i_case = 0;
  for (const Study& st : studies) n_cases += st.cases.size();
  for (const Study& st : studies) {
    StudyResult sr{st, {}};
    for (const Case& c : st.cases) {
      ++i_case;
      std::fprintf(stderr, "[%zu/%zu] %s\n", i_case, n_cases, c.id.c_str());
      const Recording rec = load_recording(render_case(c, o, &render_s, &reused));
      for (const WorkSize& w : c.work) {
        // The VO baseline runs beside both engines on the same frames.
        for (EngineKind kind : {EngineKind::kFixed, EngineKind::kFloat, EngineKind::kVo}) {
          RunOptions ro;
          ro.engine = kind;
          ro.size = {w.width, w.height};
          ro.ignore_distortion = lens_variant(c).ignore_distortion;
          ro.gyro_offset_learning = gyro_variant(c).learning;
          double gyro_offset = 0;  // as learned by the end of the run
          ro.sink = [&gyro_offset](const EngineEstimate& e) { gyro_offset = e.gyro_offset; };
          RunResult r;
          try {
            r = run_recording(rec, ro, nullptr);
          } catch (const RecordingError& e) {
            if (kind != EngineKind::kVo) throw;
            std::fprintf(stderr, "    vo refused the rig: %s\n", e.what());  // its cells read "-"
            continue;
          }
          CaseResult cr;
          cr.c = c;
          cr.work = w;
          cr.engine = kind;
          cr.metrics = compute_metrics(r.track);
          cr.behaviour = flag_behaviour(r.track);
          cr.bias_percent = bias_percent(r.track);
          cr.rms_after = rms_after(r.track);
          cr.gaps = rec.gaps;
          cr.run_s = r.wall_s;
          cr.step_us = r.frames ? 1e6 * r.step_s / static_cast<double>(r.frames) : 0;
          cr.gyro_offset = gyro_offset;
          cr.track = r.track;
          if (kind == EngineKind::kFixed && &w == &c.work.front()) {
            const std::string name = c.id + "_" + std::to_string(w.width) + "x" + std::to_string(w.height) + ".svg";
            write_track_svg((plot_dir / name).string(), r.track,
                            c.label + " at " + std::to_string(w.width) + "x" + std::to_string(w.height) + ", fixed engine");
            cr.plot = (fs::path(doc.stem()) / name).string();
          }
          sr.cases.push_back(cr);
        }
      }
    }
    results.push_back(sr);
  }
  std::vector<Section> sections;
  const SectionContext ctx{o.out, o.scenarios, o.slider_data, o.threads, o.quick};
  for (auto* make : selected_sections(o)) sections.push_back(make(ctx));
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::ofstream out(o.doc);
  if (!out) throw std::runtime_error(o.doc + ": cannot write");
  out << results_markdown(results, sections, o.quick, secs, render_s, reused);
  std::fprintf(stderr, "wrote %s (%.0f s)\n", o.doc.c_str(), secs);
  return 0;
}

}  // namespace

int reproduce_main(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&](const char* name) -> std::string {
      if (i + 1 >= argc) throw std::invalid_argument(std::string(name) + " needs a value");
      return argv[++i];
    };
    try {
      if (a == "--help" || a == "-h") {
        usage(stdout);
        return 0;
      } else if (a == "--quick") {
        o.quick = true;
      } else if (a == "--out") {
        o.out = value("--out");
      } else if (a == "--only") {
        o.only = value("--only");
      } else if (a == "--doc") {
        o.doc = value("--doc");
        o.doc_given = true;
      } else if (a == "--scenarios") {
        o.scenarios = value("--scenarios");
      } else if (a == "--slider-data") {
        o.slider_data = value("--slider-data");
      } else if (a == "--threads") {
        o.threads = std::stoi(value("--threads"));
        if (o.threads < 1 || o.threads > 64) throw std::invalid_argument("--threads must be 1..64");
      } else {
        throw std::invalid_argument("unknown option '" + a + "'");
      }
    } catch (const std::exception& e) {
      std::fprintf(stderr, "lumavel-sim reproduce: %s\n(see lumavel-sim reproduce --help)\n", e.what());
      return 2;
    }
  }
  if (selected_studies(o).empty() && selected_sections(o).empty()) {
    std::fprintf(stderr, "lumavel-sim reproduce: --only '%s': no study title contains it\n(see lumavel-sim reproduce --help)\n",
                 o.only.c_str());
    return 2;
  }
  if (!o.only.empty() && !o.doc_given) o.doc = o.out + "/results.md";  // a partial page never replaces the full one
  try {
    return run(o);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "lumavel-sim reproduce: %s\n", e.what());
    return 1;
  }
}

}  // namespace lumavel::host
