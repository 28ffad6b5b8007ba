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
#include "lumavel/host/render/recording_renderer.hpp"
#include "lumavel/host/render/scenario_loader.hpp"
#include "lumavel/host/run_recording.hpp"
#include "lumavel/host/track_plot.hpp"
#include "results_markdown.hpp"
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
};

void usage(std::FILE* f) {
  std::fputs(
      "usage: lumavel-sim reproduce [--quick] [--out DIR] [--doc FILE] [--scenarios DIR] [--threads N]\n"
      "\n"
      "Renders the paper's studies (Section IV-B simulations, Table I resolutions,\n"
      "Table II exposures, the trolley, a turning run, untextured/dark/dropped\n"
      "frames), runs the fixed-point and the double-precision engines on each and\n"
      "writes the paper's figures and ours side by side to FILE, with plots in a\n"
      "folder next to it. Renders are cached in DIR between runs.\n"
      "\n"
      "  --quick          a small subset (40x30 and below, short runs) for CI\n"
      "  --out DIR        recordings and plots (default out/reproduce)\n"
      "  --doc FILE       results page (default docs/results.md; plots in docs/results/)\n"
      "  --scenarios DIR  scenario folder (default the source tree's host_sim/scenarios)\n"
      "  --threads N      render threads (default 2)\n",
      f);
}

// Renders a case unless an identical render is already cached; adds the
// render time to *render_s, or counts the reuse in *reused.
std::string render_case(const Case& c, const Options& o, double* render_s, int* reused) {
  const std::string dir = o.out + "/rec/" + c.id;
  std::ostringstream stamp;
  const std::string scen = o.scenarios + "/" + c.scenario;
  stamp << scen << " " << fs::last_write_time(scen).time_since_epoch().count() << " " << c.render_w << "x"
        << c.render_h << " e" << c.exposure << " d" << c.duration << "\n";
  const std::string stamp_path = dir + "/.render-stamp";
  {
    std::ifstream in(stamp_path);
    std::stringstream have;
    have << in.rdbuf();
    if (in && have.str() == stamp.str()) {
      ++*reused;
      return dir;
    }
  }
  fs::remove_all(dir);
  render::Scenario s = render::load_scenario(scen);
  render::Overrides ov;
  ov.width = c.render_w;
  ov.height = c.render_h;
  ov.exposure_frames = c.exposure;
  ov.duration_s = c.duration;
  render::apply_overrides(s, ov);
  render::RenderOptions ro;
  ro.threads = o.threads;
  const render::RenderSummary sum = render::render_recording(s, dir, ro);
  std::fprintf(stderr, "    rendered %d frame pairs in %.1f s\n", sum.frames, sum.seconds);
  *render_s += sum.seconds;
  std::ofstream(stamp_path) << stamp.str();
  return dir;
}

int run(const Options& o) {
  const auto t0 = std::chrono::steady_clock::now();
  const std::vector<Study> studies = paper_studies(o.quick);
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
        for (EngineKind kind : {EngineKind::kFixed, EngineKind::kFloat}) {
          RunOptions ro;
          ro.engine = kind;
          ro.size = {w.width, w.height};
          const RunResult r = run_recording(rec, ro, nullptr);
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
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::ofstream out(o.doc);
  if (!out) throw std::runtime_error(o.doc + ": cannot write");
  out << results_markdown(results, o.quick, secs, render_s, reused);
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
      } else if (a == "--doc") {
        o.doc = value("--doc");
      } else if (a == "--scenarios") {
        o.scenarios = value("--scenarios");
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
  try {
    return run(o);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "lumavel-sim reproduce: %s\n", e.what());
    return 1;
  }
}

}  // namespace lumavel::host
