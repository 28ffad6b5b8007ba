// Gyro zero-rate offset study (issue 6): gyro_offset_standstill.yaml (2 s
// standstill, slalom along a photo wall, a second standstill, restart; 2 deg/s
// offset, MPU-6050-like noise) rendered with its offset and, from the same
// seed, without it; each render run with offset learning (the default) and
// without (run --no-gyro-offset-learning).
#include <cmath>
#include <cstdio>
#include <sstream>

#include "results_markdown.hpp"
#include "studies.hpp"

namespace lumavel::host::reproduce {
namespace {

struct GyroCase {
  const char* id;
  const char* render_id;  // the learning-off case shares the learning-on case's render
  bool no_offset, learning;
  const char* label;
};

const GyroCase kCases[] = {
    {"gyro_offset_learned", "gyro_offset", false, true, "2 deg/s offset, learned at standstill (default)"},
    {"gyro_offset_raw", "gyro_offset", false, false, "2 deg/s offset, not learned (`--no-gyro-offset-learning`)"},
    {"gyro_none_learned", "gyro_none", true, true, "no offset, learning on"},
    {"gyro_none_raw", "gyro_none", true, false, "no offset, learning off"},
};

// Windows of the scenario's timeline (s since the first frame): the
// standstill once the offset can have been learned (still_min 0.5 s, then
// tau), and the slalom at constant 0.8 m/s after the 1.5 s start.
constexpr double kStillFrom = 1.0, kStillTo = 2.0;
constexpr double kCruiseFrom = 3.5, kCruiseTo = 9.5;
constexpr double kDegPerRad = 57.29577951308232;

const GyroCase* find_case(const std::string& id) {
  for (const GyroCase& g : kCases)
    if (id == g.id) return &g;
  return nullptr;
}

// Mean of v_est - v_true over [t0, t1) s since the first frame (NaN: none).
double mean_error(const std::vector<TrackPoint>& track, double t0, double t1) {
  double sum = 0;
  size_t n = 0;
  for (const TrackPoint& p : track) {
    const double t = static_cast<double>(p.t_ns - track.front().t_ns) * 1e-9;
    if (t < t0 || t >= t1 || std::isnan(p.v_true)) continue;
    sum += p.v_est - p.v_true;
    ++n;
  }
  return n ? sum / static_cast<double>(n) : std::nan("");
}

std::string fmt(const char* f, double v) {
  if (std::isnan(v)) return "-";
  char b[64];
  std::snprintf(b, sizeof b, f, v);
  return b;
}

const CaseResult* find(const StudyResult& sr, const std::string& id, const WorkSize& w, EngineKind k) {
  for (const CaseResult& c : sr.cases)
    if (c.c.id == id && c.work.width == w.width && c.work.height == w.height && c.engine == k) return &c;
  return nullptr;
}

}  // namespace

Study gyro_offset_study(bool quick) {
  Study st{"Gyro zero-rate offset",
           "`gyro_offset_standstill.yaml`: the rig stands still for 2 s in front of a photo wall 2 m away, "
           "then slaloms along it at 0.8 m/s (R = 3 m arcs), stops for 2 s and starts again; the gyro has a "
           "2 deg/s zero-rate offset and MPU-6050-like noise (0.005 deg/s/sqrt(Hz)). Rendered at 160x120, 14 s "
           "(quick: 80x60, 6 s), with the offset and, from the same seed, without it; each render run with the "
           "offset learned at standstill (the default) and without (`run --no-gyro-offset-learning`). Mean "
           "errors: V_est - V over 1-2 s (standstill, after still_min) and over 3.5-9.5 s (cruising after the "
           "start); E from the first frame, so it includes the lag of V (tau = 0.1 s) while accelerating. "
           "Offset: learned by the end of the run, fixed engine. VO: the keypoint stereo VO, which takes the "
           "gyro as it reads (its rotation over each frame interval); learning on or off is the same run for it.",
           "gyro",
           {}};
  const std::vector<WorkSize> work = quick ? std::vector<WorkSize>{{40, 30}} : std::vector<WorkSize>{{40, 30}, {160, 120}};
  const double duration = quick ? 6 : -1;
  const int rw = quick ? 80 : -1, rh = quick ? 60 : -1;
  for (const GyroCase& g : kCases)
    st.cases.push_back({g.id, "gyro_offset_standstill.yaml", rw, rh, -1, duration, work, g.label, -1, ""});
  return st;
}

GyroVariant gyro_variant(const Case& c) {
  GyroVariant v;
  const GyroCase* g = find_case(c.id);
  if (!g) {
    v.render_id = lens_variant(c).render_id;
    return v;
  }
  v.no_offset = g->no_offset;
  v.learning = g->learning;
  v.render_id = g->render_id;
  return v;
}

std::string gyro_offset_table(const StudyResult& sr, std::vector<SectionTarget>& targets) {
  std::ostringstream md;
  md << "| case | working | VO: E | fixed: E | float: E | mean error at standstill | mean error cruising after it | "
        "VO: mean error cruising | offset learned | plot |\n|---|---|---|---|---|---|---|---|---|---|\n";
  for (const CaseResult& c : sr.cases) {
    if (c.engine != EngineKind::kFixed) continue;
    const GyroCase* g = find_case(c.c.id);
    if (!g) continue;
    const CaseResult* d = find(sr, c.c.id, c.work, EngineKind::kFloat);
    // The VO takes the gyro as it reads (no learning): on and off are the same run for it.
    const CaseResult* v = find(sr, c.c.id, c.work, EngineKind::kVo);
    const double still = mean_error(c.track, kStillFrom, kStillTo);
    const double cruise = mean_error(c.track, kCruiseFrom, kCruiseTo);
    const std::string size = std::to_string(c.work.width) + "x" + std::to_string(c.work.height);
    md << "| " << g->label << " | " << size << " | " << (v ? fmt("%.2f %%", v->metrics.e_percent) : "-") << " | "
       << fmt("%.2f %%", c.metrics.e_percent) << " | " << (d ? fmt("%.2f %%", d->metrics.e_percent) : "-") << " | "
       << fmt("%+.4f m/s", still) << " | " << fmt("%+.4f m/s", cruise) << " | "
       << (v ? fmt("%+.4f m/s", mean_error(v->track, kCruiseFrom, kCruiseTo)) : "-") << " | "
       << (g->learning ? fmt("%+.4f deg/s", c.gyro_offset * kDegPerRad) : std::string("off")) << " | "
       << (c.plot.empty() ? "" : "[svg](" + c.plot + ")") << " |\n";
    // Issue 6: with a 2 deg/s offset and no calibration, V right after a 2 s standstill.
    if (!g->no_offset && g->learning && c.work.width == 40) {
      const double off = c.gyro_offset * kDegPerRad;
      targets.push_back({"gyro offset 2 deg/s: learned in a 2 s standstill, 40x30", "2 +- 0.02 deg/s",
                         fmt("%.4f deg/s", off), std::fabs(off - 2) <= 0.02});
      targets.push_back({"gyro offset 2 deg/s, learned: mean V error cruising after the standstill, 40x30",
                         "<= 0.01 m/s", fmt("%+.4f m/s", cruise), std::fabs(cruise) <= 0.01});
    }
  }
  return md.str();
}

}  // namespace lumavel::host::reproduce
