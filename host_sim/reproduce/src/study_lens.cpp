// Lens distortion study: each lens scenario rendered once through its lens
// and once without it (same seed), the lens render run three times
// (corrected, the default; corrected by column tables only, --lens-columns;
// read as pinhole, --ignore-distortion), at the product's 40x30 and at
// 160x120.
#include <cmath>
#include <cstdio>
#include <sstream>

#include "results_markdown.hpp"
#include "studies.hpp"

namespace lumavel::host::reproduce {
namespace {

struct LensScene {
  const char* id;
  const char* file;
  const char* label;
  const char* spin_target;  // the spin's target row, or nullptr
};

// distorted_wall: straight pass, hfov 50, mild lens (the correction cannot
// show there: the geometry cancels for a pure translation); the wide_lens
// scenes: strong barrel, turning hard, at hfov 90 (issue 11's targets) and
// at 60 and 120.
const LensScene kScenes[] = {
    {"lens_slalom", "wide_lens_slalom.yaml", "slalom, hfov 90, k1 -0.22", nullptr},
    {"lens_spin", "wide_lens_spin.yaml", "spin in place, hfov 90, k1 -0.22", "wide-lens spin in place"},
    {"lens_slalom60", "wide_lens_slalom_hfov60.yaml", "slalom, hfov 60, k1 -0.22", nullptr},
    {"lens_spin60", "wide_lens_spin_hfov60.yaml", "spin in place, hfov 60, k1 -0.22", "spin in place at hfov 60"},
    {"lens_slalom120", "wide_lens_slalom_hfov120.yaml", "slalom, hfov 120, k1 -0.22", nullptr},
    {"lens_spin120", "wide_lens_spin_hfov120.yaml", "spin in place, hfov 120, k1 -0.22", "spin in place at hfov 120"},
    {"lens_wall", "distorted_wall.yaml", "straight wall pass, hfov 50, k1 -0.14", nullptr},
};

// Case ids: scene id + variant suffix.
constexpr const char* kUndistorted = "_undistorted";
constexpr const char* kCorrected = "_corrected";
constexpr const char* kIgnored = "_ignored";
constexpr const char* kColumns = "_columns";

bool ends_with(const std::string& s, const std::string& end) {
  return s.size() >= end.size() && s.compare(s.size() - end.size(), end.size(), end) == 0;
}

bool is_lens_case(const std::string& id) {
  for (const LensScene& s : kScenes)
    for (const char* suffix : {kUndistorted, kCorrected, kIgnored, kColumns})
      if (id == std::string(s.id) + suffix) return true;
  return false;
}

std::string cell(const CaseResult* c, bool e_defined) {
  if (!c) return "-";
  const RunMetrics& m = c->metrics;
  char b[96];
  if (e_defined)
    std::snprintf(b, sizeof b, "%.2f %% / %.3f / %+.3f", m.e_percent, m.worst_after, m.mean_after);
  else
    std::snprintf(b, sizeof b, "- / %.3f / %+.3f", m.worst_after, m.mean_after);
  return b;
}

}  // namespace

Study lens_study(bool quick) {
  Study st{"Lens distortion",
           "Each scene rendered at 160x120 (quick: 80x60, 3 s) through its radial-tangential lens and, from the same seed, "
           "without it; the lens render is run with the correction (each frame resampled onto the pinhole of its "
           "intrinsics before binning, the default), with per-column tables only (each column's yaw and elevation "
           "scale from the undistorted geometry, the frames binned as they are: what a device does with the "
           "lens tables `lumavel-read config set` sends it; `run --lens-columns`) and read as pinhole (`run "
           "--ignore-distortion`). Cells: E (eq. 22) / "
           "worst |err| after 1 s (m/s) / mean error after 1 s (m/s), fixed engine; E is undefined for "
           "the spin in place (V = 1 mm/s). Read as pinhole, a lens leaves a spurious V in the rotation "
           "term, proportional to the yaw rate. VO: the keypoint stereo VO undistorting its points with "
           "sensor.yaml's lens model (corrected) and without it (ignored).",
           "lens",
           {}};
  const std::vector<WorkSize> work = quick ? std::vector<WorkSize>{{40, 30}} : std::vector<WorkSize>{{40, 30}, {160, 120}};
  // Quick (CI): 3 s rendered at 80x60, enough for 40x30 (the lens render is the slow part).
  const double duration = quick ? 3 : -1;
  const int rw = quick ? 80 : 160, rh = quick ? 60 : 120;
  for (const LensScene& s : kScenes) {
    const std::string id = s.id;
    st.cases.push_back({id + kUndistorted, s.file, rw, rh, -1, duration, work, s.label, -1, ""});
    st.cases.push_back({id + kCorrected, s.file, rw, rh, -1, duration, work, s.label, -1, ""});
    st.cases.push_back({id + kColumns, s.file, rw, rh, -1, duration, work, s.label, -1, ""});
    st.cases.push_back({id + kIgnored, s.file, rw, rh, -1, duration, work, s.label, -1, ""});
  }
  return st;
}

LensVariant lens_variant(const Case& c) {
  LensVariant v;
  v.render_id = c.id;
  if (!is_lens_case(c.id)) return v;
  v.no_lens = ends_with(c.id, kUndistorted);
  // Both share the corrected case's frames: estimated as pinhole, or with column tables.
  for (const char* suffix : {kIgnored, kColumns})
    if (ends_with(c.id, suffix)) {
      (suffix == kIgnored ? v.ignore_distortion : v.by_columns) = true;
      v.render_id = c.id.substr(0, c.id.size() - std::string(suffix).size()) + kCorrected;
    }
  return v;
}

std::string lens_table(const StudyResult& sr, std::vector<SectionTarget>& targets) {
  auto find = [&](const std::string& id, const WorkSize& w, EngineKind k) -> const CaseResult* {
    for (const CaseResult& c : sr.cases)
      if (c.c.id == id && c.work.width == w.width && c.work.height == w.height && c.engine == k) return &c;
    return nullptr;
  };
  std::ostringstream md;
  md << "| scene | working | undistorted | distorted, corrected | distorted, column tables only | distorted, "
        "ignored | float: corrected E | VO: corrected / ignored E |\n"
        "|---|---|---|---|---|---|---|---|\n";
  for (const LensScene& s : kScenes) {
    const std::string id = s.id;
    for (const CaseResult& c : sr.cases)
      if (c.c.id == id + kCorrected && c.engine == EngineKind::kFixed) {
        const WorkSize w = c.work;
        const bool e_defined = c.metrics.samples > c.metrics.excluded_slow;
        const CaseResult* fc = find(id + kCorrected, w, EngineKind::kFloat);
        char fe[32] = "-", ve[64] = "-";
        if (fc && e_defined) std::snprintf(fe, sizeof fe, "%.2f %%", fc->metrics.e_percent);
        const CaseResult* vc = find(id + kCorrected, w, EngineKind::kVo);
        const CaseResult* vi = find(id + kIgnored, w, EngineKind::kVo);
        if (vc && vi && e_defined)
          std::snprintf(ve, sizeof ve, "%.2f %% / %.2f %%", vc->metrics.e_percent, vi->metrics.e_percent);
        // Issue 11's targets on the wide lens (hfov 90, k1 -0.22).
        const CaseResult* und = find(id + kUndistorted, w, EngineKind::kFixed);
        const std::string at = std::to_string(w.width) + "x" + std::to_string(w.height);
        char got[64];
        if (id == "lens_slalom") {
          std::snprintf(got, sizeof got, "%.2f %%", c.metrics.e_percent);
          targets.push_back({"wide-lens slalom, corrected, E at " + at, "<= 3 %", got, c.metrics.e_percent <= 3});
          if (und) {
            const double gap = c.metrics.e_percent - und->metrics.e_percent;
            std::snprintf(got, sizeof got, "%.2f %% (%+.2f)", c.metrics.e_percent, gap);
            char want[64];
            std::snprintf(want, sizeof want, "within 0.3 points of %.2f %%", und->metrics.e_percent);
            targets.push_back({"wide-lens slalom, corrected against undistorted, at " + at, want, got,
                               std::fabs(gap) <= 0.3});
          }
        }
        if (s.spin_target) {
          std::snprintf(got, sizeof got, "%.3f m/s", c.metrics.worst_after);
          targets.push_back({std::string(s.spin_target) + ", corrected, worst |V| after 1 s at " + at, "<= 0.03 m/s",
                             got, c.metrics.worst_after <= 0.03});
        }
        md << "| " << s.label << " | " << w.width << "x" << w.height << " | "
           << cell(find(id + kUndistorted, w, EngineKind::kFixed), e_defined) << " | " << cell(&c, e_defined)
           << " | " << cell(find(id + kColumns, w, EngineKind::kFixed), e_defined) << " | "
           << cell(find(id + kIgnored, w, EngineKind::kFixed), e_defined) << " | " << fe << " | " << ve
           << " |\n";
      }
  }
  md << "\nReading: undistorting the frames makes a lens camera a pinhole camera for the estimator: the "
        "corrected runs follow the undistorted ones (the spin's spurious V is the pinhole's), where the column "
        "tables alone leave the part of the lens that bends each column across its rows (docs/design.md, \"Lens "
        "distortion\"). At hfov 90 the columns sum one elevation band by default (from 80 degrees; docs/design.md, "
        "\"Column profile\"): without it the pinhole itself leaves twice the spin's spurious V (0.04 m/s), the "
        "column sums' geometry on a wide camera. At hfov 60 the kernels are narrower in angle and the same turn "
        "moves the image further across them in a frame: the spin's spurious V grows with the yaw rate (about "
        "-0.03 m/s at 1.4 rad/s; in part the rotation term's trapezoid over a finite turn, docs/design.md, \"Finite "
        "step\", measured and not taken), and on its slalom the VO, whose keypoints see the narrow view at a finer "
        "angle, is ahead at 160x120. At hfov 120 the corrected lens stays with the undistorted camera and the VO "
        "falls behind (the wall at grazing angles in the image's outer columns).\n";
  md << "\nPlots (fixed engine, first working size):";
  for (const CaseResult& c : sr.cases)
    if (c.engine == EngineKind::kFixed && !c.plot.empty()) md << " [" << c.c.id << "](" << c.plot << ")";
  md << "\n";
  return md.str();
}

}  // namespace lumavel::host::reproduce
