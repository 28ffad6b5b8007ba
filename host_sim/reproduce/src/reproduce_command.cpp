#include "lumavel/host/reproduce_command.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

#include "lumavel/core/status.hpp"
#include "lumavel/host/cli.hpp"
#include "lumavel/host/output_file.hpp"
#include "lumavel/host/path_check.hpp"
#include "lumavel/host/recording.hpp"
#include "lumavel/host/render/frame_renderer.hpp"
#include "lumavel/host/render/scenario_loader.hpp"
#include "lumavel/host/render/scene.hpp"
#include "lumavel/host/run_recording.hpp"
#include "lumavel/host/slider_dataset.hpp"
#include "lumavel/host/track_plot.hpp"
#include "render_cache.hpp"
#include "results_markdown.hpp"
#include "sections.hpp"
#include "source_tree.hpp"
#include "studies.hpp"

namespace lumavel::host {
namespace fs = std::filesystem;
using namespace reproduce;

namespace {

struct Options {
  bool quick = false;
  std::string out;          // "": the source tree's out/reproduce (quick: out/reproduce-quick)
  std::string doc;          // "": docs/results.md (quick or --only: OUT/results.md)
  std::string scenarios;    // "": the source tree's host_sim/scenarios
  int threads = 2;
  std::string only;         // run only the studies whose title contains this
  std::string slider_data;  // "": ../shared/data/slider_depth next to the source tree
};

const char* const kDescription =
    "render and run the paper's studies, write docs/results.md\n\n"
    "Renders the paper's studies (Section IV-B simulations, Table I resolutions,\n"
    "Table II exposures, the trolley, a turning run, untextured/dark/dropped\n"
    "frames, lens distortion, gyro offset), runs the fixed-point and the\n"
    "double-precision engines and the keypoint stereo VO baseline (--engine vo) on\n"
    "each and writes the paper's figures, the VO's and ours side by side to a\n"
    "results page, with plots in a folder next to it; then calibrates\n"
    "the misalignment of rendered rigs and runs the real slider_depth recording when\n"
    "its data is there. Renders are cached in OUT between runs.\n"
    "\n"
    "Every default path is in the source tree that holds this binary's build, never\n"
    "in the current folder. The full run writes docs/results.md; --quick and --only\n"
    "never do: their page goes to OUT/results.md and says it is partial. Progress\n"
    "and a time estimate go to standard error.";

std::string render_dir(const Case& c, const Options& o) { return o.out + "/rec/" + gyro_variant(c).render_id; }

std::string render_key(const Case& c) {
  const LensVariant lens = lens_variant(c);
  const GyroVariant gyro = gyro_variant(c);
  std::ostringstream key;
  key << c.render_w << "x" << c.render_h << " e" << c.exposure << " d" << c.duration
      << (lens.no_lens ? " no-lens" : "") << (gyro.no_offset ? " no-gyro-offset" : "")
      << (c.camera_mismatch.empty() ? "" : " mismatch " + c.camera_mismatch);
  return key.str();
}

// The case's changes to its scenario (resolution, exposure, length, lens, gyro).
void adjust_scenario(const Case& c, render::Scenario& s) {
  render::Overrides ov;
  ov.width = c.render_w;
  ov.height = c.render_h;
  ov.exposure_frames = c.exposure;
  ov.duration_s = c.duration;
  ov.camera_mismatch = c.camera_mismatch;
  render::apply_overrides(s, ov);
  if (lens_variant(c).no_lens) s.camera.distortion = {};  // same seed and motion, pinhole camera
  if (gyro_variant(c).no_offset) s.imu.gyro_bias_z = 0;   // same seed, images and gyro noise
}

// Renders a case unless an identical render is already cached.
std::string render_case(const Case& c, const Options& o) {
  const std::string dir = render_dir(c, o);  // gyro_variant's render_id is lens's for other cases
  const CachedRender r = render_cached(o.scenarios + "/" + c.scenario, dir, render_key(c),
                                       [&](render::Scenario& s) { adjust_scenario(c, s); }, o.threads);
  if (!r.reused) std::fprintf(stderr, "    rendered %d frame pairs in %.1f s\n", r.frames, r.seconds);
  return dir;
}

// What a case will cost, for the time estimate.
struct CaseCost {
  double render_s = 0;  // predicted by a sample render (0 when cached)
  double run_units = 0;  // the engines' work, in units whose rate is learned as cases finish
};

// A render's cost depends on too much to model (planes in view, lens
// distortion, photo textures): it is measured on a sample, three frames of
// both cameras at a quarter of the resolution each way (the same work per
// pixel, 1/16 of the pixels), scaled to the full size, to the sub-frames the
// full size draws (motion blur spans more pixels there), to every frame and
// to the render threads.
double sample_render_seconds(const render::Scenario& full, int threads) {
  render::Scenario s = full;
  render::Overrides small;
  small.width = std::max(8, s.camera.width / 4);
  small.height = std::max(6, s.camera.height / 4);
  render::apply_overrides(s, small);
  const auto t0 = std::chrono::steady_clock::now();
  const render::Scene scene = render::build_scene(s);  // the scene does not depend on the camera
  const render::FrameRenderer fr(s, scene), fr_full(full, scene);
  const double build = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const int n = fr.frame_count();
  const double pixels = static_cast<double>(full.camera.width) * full.camera.height /
                        (static_cast<double>(s.camera.width) * s.camera.height);
  double frame_s = 0;
  std::vector<uint8_t> px;
  for (int i : {n / 4, n / 2, 3 * n / 4})
    for (int cam = 0; cam < 2; ++cam) {
      const auto a = std::chrono::steady_clock::now();
      const render::FrameStats st = fr.render(i, cam, px);
      const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - a).count();
      frame_s += t * pixels * fr_full.subframes(fr.frame_time(i), cam) / std::max(1, st.subframes) / 3;
    }
  // Each frame pair also costs two PNG files: about 0.5 ms on top of the pixels.
  constexpr double kFilesPerFrameS = 0.0005;
  return build + (frame_s + kFilesPerFrameS) * n / std::max(1, threads);
}

// `planned`: the renders of the cases before this one (rendered by then).
CaseCost case_cost(const Case& c, const Options& o, std::set<std::string>& planned) {
  render::Scenario s = render::load_scenario(o.scenarios + "/" + c.scenario);
  adjust_scenario(c, s);
  CaseCost k;
  const std::string render = render_dir(c, o) + " " + render_key(c);
  if (!render_is_cached(o.scenarios + "/" + c.scenario, render_dir(c, o), render_key(c)) && planned.insert(render).second)
    k.render_s = sample_render_seconds(s, o.threads);
  // Per frame and working size: decoding and binning the rendered frames,
  // and the three engines, of which the VO costs most (about 2 ms a frame
  // plus its share of the pixels, measured on 40x30 and 160x120).
  const double frames = s.duration_s * s.camera.rate_hz;
  for (const WorkSize& w : c.work)
    k.run_units += frames * (static_cast<double>(s.camera.width) * s.camera.height + 16000.0 + 2.0 * w.width * w.height);
  return k;
}

std::string duration_text(double s) {
  char b[64];
  if (s < 90) std::snprintf(b, sizeof b, "%.0f s", s);
  else std::snprintf(b, sizeof b, "%.0f min", s / 60);
  return b;
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
std::vector<std::pair<const char*, Section (*)(const SectionContext&)>> selected_sections(const Options& o) {
  std::vector<std::pair<const char*, Section (*)(const SectionContext&)>> kept;
  if (std::string(kCalibrationTitle).find(o.only) != std::string::npos)
    kept.emplace_back(kCalibrationTitle, calibration_section);
  if (std::string(kRealRecordingTitle).find(o.only) != std::string::npos)
    kept.emplace_back(kRealRecordingTitle, real_recording_section);
  return kept;
}

CaseResult run_case(const Case& c, const Recording& rec, const WorkSize& w, EngineKind kind) {
  RunOptions ro;
  ro.engine = kind;
  ro.size = {w.width, w.height};
  ro.ignore_distortion = lens_variant(c).ignore_distortion;
  ro.lens_by_columns = lens_variant(c).by_columns;
  ro.gyro_offset_learning = gyro_variant(c).learning;
  double gyro_offset = 0;  // as learned by the end of the run
  ro.sink = [&gyro_offset](const EngineEstimate& e) { gyro_offset = e.gyro_offset; };
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
  cr.step_us = r.frames ? 1e6 * r.step_s / static_cast<double>(r.frames) : 0;
  cr.gyro_offset = gyro_offset;
  cr.track = r.track;
  cr.rendered = {rec.cam[0].width, rec.cam[0].height};
  cr.rendered_s = rec.frames.empty() ? 0
                  : static_cast<double>(rec.frames.back().t_ns - rec.frames.front().t_ns) * 1e-9 + rec.frame_period_s;
  return cr;
}

int run(const Options& o) {
  const auto t0 = std::chrono::steady_clock::now();
  auto elapsed = [&t0] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(); };
  const std::vector<Study> studies = selected_studies(o);
  const fs::path doc(o.doc);
  const fs::path plot_dir = doc.parent_path() / doc.stem();
  // Checked before (check_outputs); what the system still refuses (a folder
  // of /sys to root) is said with the option and the reason.
  for (const auto& [folder, option] : {std::pair<std::string, const char*>{plot_dir.string(), "the plots of --doc"},
                                       std::pair<std::string, const char*>{o.out, "--out"}}) {
    std::error_code ec;
    fs::create_directories(folder, ec);
    if (ec) throw std::runtime_error(shown_path(folder) + " (" + option + "): cannot create the folder: " + ec.message());
  }
  const std::string machine = machine_description();
  std::fprintf(stderr, "reproduce: page %s, renders in %s, on %s\n", o.doc.c_str(), o.out.c_str(), machine.c_str());

  std::vector<CaseCost> costs;
  std::set<std::string> planned;
  for (const Study& st : studies)
    for (const Case& c : st.cases) costs.push_back(case_cost(c, o, planned));
  // The time left: the sampled renders, corrected by how the finished ones
  // compared with their samples, and the engines' units at the rate seen so far.
  double render_predicted_done = 0, render_actual_done = 0, run_units_done = 0, run_s_done = 0;
  auto time_left = [&](size_t from) {
    const double render_factor = render_predicted_done > 0 ? render_actual_done / render_predicted_done : 1.0;
    double render_left = 0, units_left = 0;
    for (size_t k = from; k < costs.size(); ++k) render_left += costs[k].render_s, units_left += costs[k].run_units;
    return render_left * render_factor + units_left * run_s_done / run_units_done;
  };

  std::vector<StudyResult> results;
  size_t i_case = 0;
  for (const Study& st : studies) {
    StudyResult sr{st, {}};
    for (const Case& c : st.cases) {
      const std::string eta = run_units_done > 0 ? duration_text(elapsed()) + " elapsed, about " +
                                                       duration_text(time_left(i_case)) + " left for the studies"
                                                 : "the time left is estimated after this case";
      std::fprintf(stderr, "[%zu/%zu] %s (%s)\n", i_case + 1, costs.size(), c.id.c_str(), eta.c_str());
      const CaseCost& cost = costs[i_case++];
      const double render_start = elapsed();
      const Recording rec = load_recording(render_case(c, o));
      if (cost.render_s > 0) render_predicted_done += cost.render_s, render_actual_done += elapsed() - render_start;
      const double run_start = elapsed();
      for (const WorkSize& w : c.work) {
        // The VO baseline runs beside both engines on the same frames.
        for (EngineKind kind : {EngineKind::kFixed, EngineKind::kFloat, EngineKind::kVo}) {
          CaseResult cr;
          try {
            cr = run_case(c, rec, w, kind);
          } catch (const RecordingError& e) {
            if (kind != EngineKind::kVo) throw;
            std::fprintf(stderr, "    vo refused the rig: %s\n", e.what());  // its cells read "-"
            continue;
          }
          if (kind == EngineKind::kFixed && &w == &c.work.front()) {
            const std::string name = c.id + "_" + std::to_string(w.width) + "x" + std::to_string(w.height) + ".svg";
            write_track_svg((plot_dir / name).string(), cr.track,
                            c.label + " at " + std::to_string(w.width) + "x" + std::to_string(w.height) + ", fixed engine");
            cr.plot = (fs::path(doc.stem()) / name).string();
          }
          sr.cases.push_back(cr);
        }
      }
      run_units_done += cost.run_units;
      run_s_done += elapsed() - run_start;
    }
    results.push_back(sr);
  }
  std::vector<Section> sections;
  const SectionContext ctx{o.out, o.scenarios, o.slider_data, o.threads, o.quick};
  for (const auto& [title, make] : selected_sections(o)) {
    std::fprintf(stderr, "[section] %s (%s elapsed)\n", title, duration_text(elapsed()).c_str());
    sections.push_back(make(ctx));
  }
  const RenderTally tally = render_tally();
  PageInfo info;
  info.quick = o.quick;
  info.only = o.only;
  info.seconds = elapsed();
  info.render_seconds = tally.seconds;
  info.renders_reused = tally.reused_from_earlier_run;
  info.machine = machine;
  // A FIFO nobody reads is refused after a short wait, as run's outputs are
  // (an ofstream waited in open() for ever, the studies done).
  // A page that cannot be written whole leaves the earlier one in place.
  write_file(o.doc, results_markdown(results, sections, info), "the page (--doc)");
  std::fprintf(stderr, "wrote %s (%s)\n", o.doc.c_str(), duration_text(info.seconds).c_str());
  return 0;
}

// The defaults come from the source tree; a partial run (--quick, --only)
// never writes the committed page.
void resolve_paths(Options& o) {
  const bool need_tree = o.out.empty() || o.doc.empty() || o.scenarios.empty() || o.slider_data.empty();
  const std::string tree = need_tree ? source_tree() : std::string();
  if (o.scenarios.empty()) o.scenarios = tree + "/host_sim/scenarios";
  if (o.slider_data.empty())
    o.slider_data = (fs::path(tree).parent_path() / "shared" / "data" / "slider_depth").string();
  if (o.out.empty()) o.out = tree + (o.quick ? "/out/reproduce-quick" : "/out/reproduce");
  const bool partial = o.quick || !o.only.empty();
  if (o.doc.empty()) o.doc = partial ? o.out + "/results.md" : tree + "/docs/results.md";
  if (!partial) return;
  // The committed page: docs/results.md of a source tree.
  std::error_code ec;
  const fs::path page = fs::weakly_canonical(o.doc, ec);
  const fs::path root = page.parent_path().parent_path();
  if (page.filename() == "results.md" && page.parent_path().filename() == "docs" &&
      fs::is_directory(root / "host_sim" / "scenarios", ec))
    throw cli::UsageError("--doc " + o.doc + ": a " + std::string(o.quick ? "--quick" : "--only") +
                          " run never replaces the full results page docs/results.md; give another file (the "
                          "default is OUT/results.md)");
}

// What the run writes, checked before its studies rather than after them
// (was: --doc naming a folder ran every study, an hour for the full run,
// then 'cannot write'; --out naming a file: 'filesystem error: cannot create
// directories: Not a directory [FILE/results]').
void check_outputs(const Options& o) {
  const auto refuse = [](const std::string& path, const std::string& option, const std::string& why) {
    if (!why.empty()) throw std::runtime_error(shown_path(path) + " (" + option + "): " + why);
  };
  // A folder that cannot be made or written in, as the page is checked (was:
  // 'filesystem error: cannot create directories: File exists [lnk/sub/results]'
  // under a dangling link, 'Permission denied [ro/results]' in a read-only one).
  refuse(o.out, "--out", why_not_a_writable_folder(o.out, "folder for the recordings and plots"));
  const fs::path doc(o.doc);
  // A new page goes in a folder that is there, as run -o's CSV does (was: its
  // folders made, a typo in them unsaid), or in --out, which the run makes.
  const std::string doc_folder = doc.parent_path().empty() ? "." : doc.parent_path().string();
  if (path_present(o.doc) || !lies_inside(doc_folder, o.out))
    refuse(o.doc, "--doc", why_not_writable(o.doc, "results page"));
  // Its plots go to the folder of its name less the extension: without one, the page's own name.
  if (doc.stem() == doc.filename())
    refuse(o.doc, "--doc", "has no extension: its plots go to the folder named as it is without one (e.g. x.md, plots in x/)");
  const std::string plots = (doc.parent_path() / doc.stem()).string();
  refuse(plots, "the plots of --doc", why_not_a_writable_folder(plots, "folder for the page's plots"));
}

}  // namespace

void add_reproduce_command(cli::Tool& tool) {
  auto o = std::make_shared<Options>();
  CLI::App* c = tool.command("reproduce", kDescription, [o] {
    if (selected_studies(*o).empty() && selected_sections(*o).empty())
      throw cli::UsageError("--only '" + o->only + "': no study title contains it");
    // Only the default dataset may be missing: a --slider-data that is no
    // folder (a typo) skipped its section as "not there", exit 0.
    if (!o->slider_data.empty())
      if (const std::string why = why_not_a_folder(o->slider_data, kSliderDatasetFolder);
          !why.empty())
        throw std::runtime_error(shown_path(o->slider_data) + " (--slider-data): " + why);
    const bool scenarios_given = !o->scenarios.empty();
    resolve_paths(*o);
    check_outputs(*o);
    // A --scenarios that is no folder (a typo) was said after the run began,
    // as its first scenario file: '/nonexist/paper_sim_aligned.yaml: does not
    // exist', the option unnamed.
    if (scenarios_given)
      if (const std::string why = why_not_a_folder(o->scenarios, "scenario folder"); !why.empty())
        throw std::runtime_error(shown_path(o->scenarios) + " (--scenarios): " + why);
    return run(*o);
  });
  c->add_flag("--quick", o->quick,
              "a small subset (40x30 and below, short runs) for CI; its page\n"
              "goes to OUT/results.md, marked quick");
  // Every title contains '' (an unset shell variable): the full run, which
  // replaces docs/results.md after an hour, where a partial one was asked.
  c->add_option("--only", o->only,
                "only the studies whose title contains TEXT (e.g. Lens); the\n"
                "page then goes to OUT/results.md unless --doc is given")
      ->type_name("TEXT")
      ->check(CLI::Validator(
          [](const std::string& v) {
            return v.empty() ? std::string("needs a part of a study title, not an empty one (which every title "
                                           "contains: the full run)")
                             : std::string();
          },
          ""));
  c->add_option("--out", o->out,
                "recordings and plots (default out/reproduce in the source\n"
                "tree; with --quick out/reproduce-quick)")
      ->type_name("DIR")
      ->check(cli::path_name());
  c->add_option("--doc", o->doc,
                "results page (default docs/results.md in the source tree,\n"
                "plots in docs/results/; with --quick or --only\n"
                "OUT/results.md)")
      ->type_name("FILE")
      ->check(cli::path_name());
  c->add_option("--scenarios", o->scenarios, "scenario folder (default the source tree's\nhost_sim/scenarios)")
      ->type_name("DIR")
      ->check(cli::path_name());
  c->add_option("--threads", o->threads, "render threads, 1..64 (default 2)")
      ->type_name("N")
      ->check(cli::whole_number_in(1, 64));
  c->add_option("--slider-data", o->slider_data,
                "the slider_depth dataset (default ../shared/data/slider_depth\n"
                "next to the source tree; its section is skipped when that is\n"
                "missing)")
      ->type_name("DIR")
      ->check(cli::path_name());
}

}  // namespace lumavel::host
