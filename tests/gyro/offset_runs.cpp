#include "offset_runs.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "lumavel/core/status.hpp"
#include "lumavel/host/recording.hpp"
#include "lumavel/host/render/recording_renderer.hpp"
#include "lumavel/host/render/scenario_loader.hpp"
#include "lumavel/host/run_recording.hpp"

namespace lumavel::host::gyro_test {
namespace {

constexpr double kDegPerRad = 57.29577951308232;

double scenario_time(const Rendered& r, uint64_t t_ns) {
  return static_cast<double>(static_cast<int64_t>(t_ns) - r.scenario.start_ns) * 1e-9;
}

// Mean of v_est - v_true over the frames with scenario time in [t0, t1).
double mean_error(const std::vector<TrackPoint>& track, const Rendered& r, double t0, double t1) {
  double sum = 0;
  size_t n = 0;
  for (const TrackPoint& p : track) {
    const double t = scenario_time(r, p.t_ns);
    if (t < t0 || t >= t1 || std::isnan(p.v_true)) continue;
    sum += p.v_est - p.v_true;
    ++n;
  }
  if (n == 0) throw std::runtime_error("no frame in the window");
  return sum / static_cast<double>(n);
}

}  // namespace

Rendered render_both(const std::string& scenario_file, int width, int height, double duration_s,
                     const std::string& dir) {
  Rendered r;
  r.scenario = render::load_scenario(scenario_file);
  render::Overrides ov;
  ov.width = width;
  ov.height = height;
  ov.duration_s = duration_s;
  render::apply_overrides(r.scenario, ov);
  const auto& segs = r.scenario.trajectory.segments;
  if (segs.size() < 2 || segs[0].v0 != 0 || segs[0].v1 != 0)
    throw std::runtime_error(scenario_file + ": must start with a standstill segment and go on moving");
  if (r.scenario.imu.gyro_bias_z == 0) throw std::runtime_error(scenario_file + ": the gyro has no offset");
  r.still_end_s = segs[0].duration_s;
  r.cruise_start_s = segs[0].duration_s + segs[1].duration_s;
  render::RenderOptions ro;
  ro.threads = 2;
  ro.progress = false;
  r.with_offset = dir + "/offset";
  render::render_recording(r.scenario, r.with_offset, ro);
  render::Scenario clean = r.scenario;  // same seed, images and gyro noise; no offset
  clean.imu.gyro_bias_z = 0;
  r.without_offset = dir + "/no_offset";
  render::render_recording(clean, r.without_offset, ro);
  return r;
}

OffsetRun run_offset(const std::string& rec_dir, const Rendered& r, EngineKind engine, bool learning,
                     int work_width, int work_height) {
  const Recording rec = load_recording(rec_dir);
  RunOptions o;
  o.engine = engine;
  o.size = {work_width, work_height};
  o.gyro_offset_learning = learning;
  OffsetRun run;
  o.sink = [&run](const EngineEstimate& e) { run.offset = e.gyro_offset; };
  run.track = run_recording(rec, o, nullptr).track;
  run.metrics = compute_metrics(run.track);
  for (size_t i = 1; i < run.track.size(); ++i)
    if (run.track[i].status & kStatusStill) {
      run.still_s += static_cast<double>(run.track[i].t_ns - run.track[i - 1].t_ns) * 1e-9;
      run.last_still_t = scenario_time(r, run.track[i].t_ns);
    }
  run.mean_err_still = mean_error(run.track, r, 1.0, r.still_end_s);
  run.mean_err_cruise = mean_error(run.track, r, r.cruise_start_s, 1e9);
  return run;
}

std::string describe(const OffsetRun& run) {
  char b[256];
  std::snprintf(b, sizeof b,
                "offset %+.4f deg/s, still %.2f s (last at %.2f s), E %.2f %%, mean err at standstill %+.4f m/s, "
                "cruising %+.4f m/s",
                run.offset * kDegPerRad, run.still_s, run.last_still_t, run.metrics.e_percent, run.mean_err_still,
                run.mean_err_cruise);
  return b;
}

}  // namespace lumavel::host::gyro_test
