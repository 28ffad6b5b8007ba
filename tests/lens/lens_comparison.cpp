#include "lens_comparison.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "lumavel/host/recording.hpp"
#include "lumavel/host/render/recording_renderer.hpp"
#include "lumavel/host/render/scenario_loader.hpp"
#include "lumavel/host/render/trajectory.hpp"
#include "lumavel/host/run_recording.hpp"

namespace lumavel::host::lens_test {
namespace {

Variant run_variant(const std::string& rec_dir, EngineKind engine, int w, int h, bool ignore_distortion,
                    RunOptions::Band band, bool by_columns = false) {
  const Recording rec = load_recording(rec_dir);
  RunOptions o;
  o.engine = engine;
  o.size = {w, h};
  o.ignore_distortion = ignore_distortion;
  o.lens_by_columns = by_columns;
  o.elevation_band = band;
  Variant v;
  v.track = run_recording(rec, o, nullptr).track;
  v.metrics = compute_metrics(v.track);
  return v;
}

// Least-squares slope through the origin of (variant - reference) against
// the true yaw rate, and the rms of the difference, after the first second.
void fit(const Variant& ref, const Variant& var, const render::Scenario& s, double& slope, double& rms) {
  if (ref.track.size() != var.track.size() || ref.track.empty())
    throw std::runtime_error("the two recordings do not have the same frames");
  const render::Trajectory traj(s.trajectory);
  double dw = 0, ww = 0, dd = 0;
  size_t n = 0;
  for (size_t i = 0; i < ref.track.size(); ++i) {
    if (ref.track[i].t_ns != var.track[i].t_ns) throw std::runtime_error("frame times differ");
    const double t = static_cast<double>(static_cast<int64_t>(ref.track[i].t_ns) - s.start_ns) * 1e-9;
    if (t < 1.0) continue;  // convergence
    const double d = var.track[i].v_est - ref.track[i].v_est, w = traj.at(t).yaw_rate;
    dw += d * w;
    ww += w * w;
    dd += d * d;
    ++n;
  }
  if (n == 0 || ww == 0) throw std::runtime_error("no turning after the first second");
  slope = dw / ww;
  rms = std::sqrt(dd / static_cast<double>(n));
}

}  // namespace

RenderedPair render_pair(const Render& r, const std::string& dir) {
  RenderedPair p;
  p.scenario = render::load_scenario(r.scenario);
  render::Overrides ov;
  ov.width = r.width;
  ov.height = r.height;
  ov.duration_s = r.duration_s;
  render::apply_overrides(p.scenario, ov);
  if (p.scenario.camera.distortion == std::array<double, 4>{})
    throw std::runtime_error(r.scenario + ": the scenario has no lens distortion");
  render::RenderOptions ro;
  ro.threads = 2;
  ro.progress = false;
  p.distorted = dir + "/distorted";
  render::render_recording(p.scenario, p.distorted, ro);
  render::Scenario pinhole = p.scenario;  // same seed, same motion, same scene
  pinhole.camera.distortion = {};
  p.undistorted = dir + "/undistorted";
  render::render_recording(pinhole, p.undistorted, ro);
  return p;
}

Comparison compare(const RenderedPair& p, EngineKind engine, int work_width, int work_height, RunOptions::Band band) {
  Comparison c;
  c.undistorted = run_variant(p.undistorted, engine, work_width, work_height, false, band);
  c.corrected = run_variant(p.distorted, engine, work_width, work_height, false, band);
  c.ignored = run_variant(p.distorted, engine, work_width, work_height, true, band);
  c.columns = run_variant(p.distorted, engine, work_width, work_height, false, band, true);
  fit(c.undistorted, c.corrected, p.scenario, c.corrected_slope, c.corrected_rms);
  fit(c.undistorted, c.columns, p.scenario, c.columns_slope, c.columns_rms);
  fit(c.undistorted, c.ignored, p.scenario, c.ignored_slope, c.ignored_rms);
  return c;
}

std::string describe(const Comparison& c) {
  char b[640], e[80] = "E undefined (V < 0.05 m/s)";
  if (c.undistorted.metrics.samples > c.undistorted.metrics.excluded_slow)
    std::snprintf(e, sizeof e, "E %.2f / %.2f / %.2f / %.2f %%", c.undistorted.metrics.e_percent,
                  c.corrected.metrics.e_percent, c.columns.metrics.e_percent, c.ignored.metrics.e_percent);
  std::snprintf(b, sizeof b,
                "%s, mean err after 1 s %+.4f / %+.4f / %+.4f / %+.4f m/s "
                "(undistorted / corrected / column tables / ignored); vs undistorted: slope on yaw rate %+.4f / "
                "%+.4f / %+.4f m/s per rad/s, rms %.4f / %.4f / %.4f m/s (corrected / column tables / ignored)",
                e, c.undistorted.metrics.mean_after, c.corrected.metrics.mean_after, c.columns.metrics.mean_after,
                c.ignored.metrics.mean_after, c.corrected_slope, c.columns_slope, c.ignored_slope, c.corrected_rms,
                c.columns_rms, c.ignored_rms);
  return b;
}

}  // namespace lumavel::host::lens_test
