// A simulated day at 60 Hz (5.18 M frames) through both engines: the rig
// drives round a textured pillar at 0.2-3 m/s with reversals, standstills
// (some too short to learn from), single dropped frames and 35-64-frame gap
// bursts; the gyro has white noise and a drifting 1 deg/s offset. Checked
// against the truth on every frame: the flags (restart, frame gap, and none
// that do not apply; 'still' only when the rig really stood still), the
// learned offset, V against the observer's ideal response to the true
// motion, distance; the integer integrals against double integrals of the
// same inputs (heading, distance); the double twin within the fixed-vs-float
// allowance with the same status everywhere; heap use flat.
// LUMAVEL_SOAK_HOURS (default 24) shortens or lengthens the day.
#include <CppUTest/TestHarness.h>
#include <malloc.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <vector>

#include "day_schedule.hpp"
#include "lumavel/core/status.hpp"
#include "lumavel/host/engine.hpp"
#include "pillar_scene.hpp"

using namespace lumavel;
using soak::DaySchedule;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kTofSplitWindowS = 3.0;  // s: a few output-smoothing and scale-filter time constants
constexpr double kScaleApart = 5e-4;      // learned scales this far apart: half the twin allowance on V

double wrap(double a) { return std::remainder(a, 2 * kPi); }

// An exact wrap into [-pi, pi), in long double.
long double wrap_exact(long double a) {
  const long double two_pi = 6.283185307179586476925286766559L;
  return a - two_pi * std::floor((a + two_pi / 2) / two_pi);
}
double q24(RateQ24 r) { return std::ldexp(static_cast<double>(r), -24); }

// The raw gyro integral as the firmware defines it (trapezoids of the
// quantised samples, linear between them), in long double.
struct GyroIntegral {
  uint64_t t0 = 0, t1 = 0;
  long double r0 = 0, r1 = 0, a0 = 0, a1 = 0;
  int n = 0;
  void push(uint64_t t, RateQ24 rate) {
    const long double r = q24(rate);
    if (n++ == 0) {
      t1 = t;
      r1 = r;
      return;
    }
    t0 = t1;
    r0 = r1;
    a0 = a1;
    t1 = t;
    r1 = r;
    a1 = a0 + (r0 + r1) / 2 * static_cast<long double>(t1 - t0) * 1e-9L;
  }
  long double at(uint64_t t) const {  // t in [t0, t1], or at or after the only sample
    if (n < 2 || t >= t1) return a1 + r1 * static_cast<long double>(t - t1) * 1e-9L;
    const long double tau = static_cast<long double>(t - t0) * 1e-9L, span = static_cast<long double>(t1 - t0) * 1e-9L;
    const long double rt = r0 + (r1 - r0) * tau / span;
    return a0 + (r0 + rt) / 2 * tau;
  }
};

struct Figures {
  uint64_t delivered = 0, status_mismatch = 0, tof_mismatch = 0, restarts = 0, frame_gaps = 0, flag_errors = 0;
  uint64_t unexpected_flags = 0, still_frames = 0, still_while_moving = 0, still_after_4mm = 0;
  uint64_t v_checked = 0, twin_outside = 0, twin_checked = 0, twin_after_tof_split = 0;
  double worst_twin_after_tof_split = 0;  // |V_fixed - V_double| / max(|V|, 0.1 m/s)
  uint64_t tof_pick_split = 0;            // both with a time of flight, from different matches
  uint64_t twin_scales_apart = 0;         // later frames while the learned scales differ by > kScaleApart
  double worst_scale_gap = 0;
  double worst_offset_error = 0, worst_heading_vs_double = 0, worst_twin_ratio = 0, worst_twin_heading = 0;
  double worst_v_error = 0, sum_v_error = 0, sum_v_error2 = 0, sum_abs_v = 0, worst_after_gap = 0;
  double distance_vs_double = 0, distance_vs_truth = 0, observed_path = 0, travelled = 0;
  double heading_vs_truth = 0, final_offset = 0, final_true_offset = 0, turns = 0;
  long heap_growth = 0;
};

double soak_hours() {
  const char* e = std::getenv("LUMAVEL_SOAK_HOURS");
  const double h = e != nullptr ? std::atof(e) : 24.0;
  return h > 0 ? h : 24.0;
}

Figures run_day(double hours, DaySchedule& day) {
  soak::PillarScene scene;
  scene.path_radius = DaySchedule::kPathRadius;
  const host::EstimatorSettings s = scene.settings();
  auto fixed = host::make_engine(host::EngineKind::kFixed, s);
  auto dbl = host::make_engine(host::EngineKind::kFloat, s);
  const auto frames = static_cast<uint64_t>(hours * 3600 * DaySchedule::kFps);
  Figures f;
  std::vector<uint8_t> a, b;
  GyroIntegral gyro;
  uint64_t pushed_until = 0;
  bool any_pushed = false;
  std::array<double, 31> travelled_ring{};  // path length at the last 31 frame times (0.5 s)
  // Previous delivered frame.
  bool have_prev = false;
  uint64_t t_prev = 0;
  double s_prev = 0, offset_prev = 0;
  long double raw_prev = 0, heading_ref = 0, distance_ref = 0;
  // The observer's ideal answer to the true motion: implicit Euler of each
  // interval's true mean velocity, restarted where the engine restarts.
  double v_ideal = 0, since_start = 0;
  bool started = false;
  double truth_observed = 0, truth_path = 0;  // true distance and path length over the intervals the engine integrates
  double travelled_prev = 0;
  uint64_t t_last_gap = 0;
  uint64_t t_tof_split = 0;
  bool tof_split_seen = false;
  long heap_at_start = 0;
  const double tau = s.tau, max_gap = s.max_gap, period = s.frame_period;
  for (uint64_t i = 0; i < frames; ++i) {
    const uint64_t t = DaySchedule::frame_time(i);
    while (!any_pushed || pushed_until < t) {  // every sample up to the first at or after t
      const soak::GyroSample g = day.next_gyro();
      fixed->push_gyro(g.t_ns, q24(g.rate));
      dbl->push_gyro(g.t_ns, q24(g.rate));
      gyro.push(g.t_ns, g.rate);
      pushed_until = g.t_ns;
      any_pushed = true;
    }
    const DaySchedule::State truth = day.at(t);
    const double moved_half_second = truth.travelled - travelled_ring[i % 31];
    travelled_ring[i % 31] = truth.travelled;
    if (!day.frame_delivered(i)) continue;
    ++f.delivered;
    const double gain = 1 + 0.1 * std::sin(2 * kPi * static_cast<double>(t) * 1e-9 / 600);  // slow lighting change
    scene.render(truth.s, gain, a, b);
    const host::EngineEstimate ef = fixed->step(t, a.data(), b.data());
    const host::EngineEstimate ed = dbl->step(t, a.data(), b.data());
    // NO_TOF is a decision on a continuous match quality (time_of_flight.hpp),
    // and so is the outvoting of a differential that points against the time
    // of flight by 2 of its sigmas (velocity_fusion.hpp): where either sits on
    // its margin, 1e-9 of arithmetic can tip it either way. Every other bit
    // must agree on every frame.
    if ((ef.status & ~kStatusNoTof) != (ed.status & ~kStatusNoTof)) {
      if (f.status_mismatch++ < 5)
        std::printf("\n  t = %.3f s: status fixed %u, double %u", static_cast<double>(t) * 1e-9, ef.status, ed.status);
    } else if (ef.status != ed.status || ef.outvoted != ed.outvoted) {
      ++f.tof_mismatch;
      t_tof_split = t;
      tof_split_seen = true;
    } else if (ef.tof_s > 0 && ed.tof_s > 0 && std::fabs(ef.tof_s / ed.tof_s - 1) > 1e-3) {
      ++f.tof_pick_split;  // two candidates about as good: each engine tracks its own
      t_tof_split = t;
      tof_split_seen = true;
    }
    f.worst_scale_gap = std::max(f.worst_scale_gap, std::fabs(ef.scale - ed.scale));
    const double dt = have_prev ? static_cast<double>(t - t_prev) * 1e-9 : 0;
    // Flags against the truth of the timing.
    const bool restart = have_prev && dt > max_gap;
    const bool gap = have_prev && dt > 1.5 * period;
    f.restarts += restart;
    f.frame_gaps += gap;
    if (((ef.status & kStatusRestarted) != 0) != restart || ((ef.status & kStatusFrameGap) != 0) != gap) ++f.flag_errors;
    if (ef.status & (kStatusGyroGap | kStatusNoLight | kStatusNoStereo | kStatusSaturated | kStatusLowTexture))
      ++f.unexpected_flags;
    if (ef.status & kStatusStill) {
      ++f.still_frames;
      // 'Still' is judged on a noisy projection of the image change (about
      // 1 mm rms here, 4 rows) against 2 mm: it may lag the first few mm of
      // motion, never more. Counted: over 4 mm; refused: over 1 cm or 0.1 m/s.
      if (moved_half_second > 0.004) ++f.still_after_4mm;
      if (moved_half_second > 0.01 || std::fabs(truth.v) > 0.1) {
        if (f.still_while_moving++ < 5)
          std::printf("\n  t = %.3f s: 'still' after %.1f mm of motion in 0.5 s (v %.3f m/s)",
                      static_cast<double>(t) * 1e-9, 1000 * moved_half_second, truth.v);
      }
    }
    // The learned offset, whenever there is one.
    if (ef.gyro_offset != 0) f.worst_offset_error = std::max(f.worst_offset_error, std::fabs(ef.gyro_offset - day.offset_at(t)));
    // Heading: the integer integral against the double one of the same inputs.
    const long double raw = gyro.at(t);
    heading_ref = have_prev ? heading_ref + (raw - raw_prev) - static_cast<long double>(offset_prev * dt) : raw;
    const double heading_gap = std::fabs(wrap(ef.heading - static_cast<double>(wrap_exact(heading_ref))));
    f.worst_heading_vs_double = std::isfinite(heading_gap) ? std::max(f.worst_heading_vs_double, heading_gap) : HUGE_VAL;
    // Distance and V: the engine integrates V over every interval but the first and restarts.
    if (have_prev && !restart) {
      distance_ref += static_cast<long double>(ef.v * dt);
      truth_observed += truth.s - s_prev;
      const double vbar = (truth.s - s_prev) / dt;
      if (!started) {
        v_ideal = vbar;
        started = true;
        since_start = 0;
      } else {
        v_ideal += (vbar - v_ideal) * dt / (tau + dt);
        since_start += dt;
      }
      truth_path += std::fabs(truth.travelled - travelled_prev);
      // V: away from the transients the flags announce (converging, and the
      // 0.5 s after a frame gap, see below), against the ideal observer.
      const double err = ef.v - v_ideal;
      if (ef.status & (kStatusFrameGap | kStatusRestarted)) t_last_gap = t;
      if (static_cast<double>(t - t_last_gap) * 1e-9 < 0.5) {
        f.worst_after_gap = std::max(f.worst_after_gap, std::fabs(err));
      } else if (!(ef.status & kStatusConverging)) {
        f.worst_v_error = std::max(f.worst_v_error, std::fabs(err));
        f.sum_v_error += err;
        f.sum_v_error2 += err * err;
        f.sum_abs_v += std::fabs(truth.v);
        ++f.v_checked;
      }
      // After the engines decided differently on a time of flight they blend
      // differently until the output smoothing forgets it (seconds), and may
      // have learned scales apart that the slow scale filter keeps for
      // minutes: those frames are measured on their own, against the speed.
      const bool after_split = tof_split_seen && static_cast<double>(t - t_tof_split) * 1e-9 < kTofSplitWindowS;
      if (after_split || std::fabs(ef.scale - ed.scale) > kScaleApart) {
        ++(after_split ? f.twin_after_tof_split : f.twin_scales_apart);
        f.worst_twin_after_tof_split =
            std::max(f.worst_twin_after_tof_split, std::fabs(ef.v - ed.v) / std::max(0.1, std::fabs(ed.v)));
      } else if (!(ef.status & kStatusConverging)) {
        const double ratio = std::fabs(ef.v - ed.v) / std::max(0.001, 0.001 * std::fabs(ed.v));
        f.worst_twin_ratio = std::max(f.worst_twin_ratio, ratio);
        ++f.twin_checked;
        if (ratio > 1) ++f.twin_outside;
      }
    }
    if (restart) {
      started = false;  // V held; the next interval re-initialises it
      since_start = 0;
    }
    f.worst_twin_heading = std::max(f.worst_twin_heading, std::fabs(wrap(ef.heading - ed.heading)));
    have_prev = true;
    t_prev = t;
    s_prev = truth.s;
    travelled_prev = truth.travelled;
    raw_prev = raw;
    offset_prev = ef.gyro_offset;
    f.distance_vs_double = std::fabs(ef.distance - static_cast<double>(distance_ref));
    f.distance_vs_truth = ef.distance - truth_observed;
    f.heading_vs_truth = wrap(ef.heading - (truth.s / DaySchedule::kPathRadius + kPi / 2));
    f.turns = static_cast<double>(std::fabs(heading_ref)) / (2 * kPi);
    f.final_offset = ef.gyro_offset;
    f.final_true_offset = day.offset_at(t);
    f.travelled = truth.travelled;
    if (i == 60000) heap_at_start = static_cast<long>(mallinfo2().uordblks);
  }
  f.observed_path = truth_path;
  f.heap_growth = static_cast<long>(mallinfo2().uordblks) - heap_at_start;
  return f;
}

}  // namespace

TEST_GROUP(SoakDay){};

TEST(SoakDay, ADayOfDrivingAgainstTheTruthAndTheTwin) {
  const double hours = soak_hours();
  DaySchedule day(2026);
  const Figures f = run_day(hours, day);
  const soak::DayCounts& c = day.counts();
  std::printf("\n  %.1f h at 60 Hz: %llu frames delivered, %d dropped, %d gap bursts (35-64 frames), %d reversals, "
              "%d standstills (%d under 0.5 s), %.1f km driven",
              hours, static_cast<unsigned long long>(f.delivered), c.dropped, c.bursts, c.reversals, c.standstills,
              c.short_standstills, f.travelled / 1000);
  std::printf("\n  flags: %llu restarts, %llu frame gaps, %llu wrong, %llu unexpected; 'still' on %llu frames, "
              "%llu of them after 4-10 mm of motion in 0.5 s, %llu after more or above 0.1 m/s",
              static_cast<unsigned long long>(f.restarts), static_cast<unsigned long long>(f.frame_gaps),
              static_cast<unsigned long long>(f.flag_errors), static_cast<unsigned long long>(f.unexpected_flags),
              static_cast<unsigned long long>(f.still_frames), static_cast<unsigned long long>(f.still_after_4mm),
              static_cast<unsigned long long>(f.still_while_moving));
  std::printf("\n  offset: worst |learned - true| %.2e rad/s; at the end %.6f (true %.6f)", f.worst_offset_error,
              f.final_offset, f.final_true_offset);
  const double n_v = static_cast<double>(std::max<uint64_t>(f.v_checked, 1));
  const double v_rms = std::sqrt(f.sum_v_error2 / n_v), v_bias = f.sum_v_error / n_v, mean_speed = f.sum_abs_v / n_v;
  std::printf("\n  V - the ideal observer on the true motion, %llu frames: rms %.4f m/s, mean %.4f m/s (%.2f %% of the mean speed "
              "%.2f m/s), worst %.4f; within 0.5 s after a frame gap: worst %.4f",
              static_cast<unsigned long long>(f.v_checked), v_rms, v_bias, 100 * v_bias / mean_speed, mean_speed,
              f.worst_v_error, f.worst_after_gap);
  std::printf("\n  distance: %.2e m off the double integral of the engine's V; %.2f m off the truth over %.1f km of path (%.3f %%)",
              f.distance_vs_double, f.distance_vs_truth, f.observed_path / 1000,
              100 * f.distance_vs_truth / std::max(1.0, f.observed_path));
  std::printf("\n  heading: worst %.2e rad off the double integral of the same inputs (wrapped, %.0f net turns); "
              "%.3f rad off the truth at the end",
              f.worst_heading_vs_double, f.turns, f.heading_vs_truth);
  std::printf("\n  twin: status differs on %llu frames; worst |V_fixed - V_double| %.1f %% of the allowance (%llu of %llu outside); "
              "worst heading gap %.2e rad",
              static_cast<unsigned long long>(f.status_mismatch), 100 * f.worst_twin_ratio,
              static_cast<unsigned long long>(f.twin_outside), static_cast<unsigned long long>(f.twin_checked),
              f.worst_twin_heading);
  std::printf("\n  heap in use grew by %ld bytes after the first 1000 s", f.heap_growth);
  std::printf("\n  twin: NO_TOF or the outvote differs on %llu of %llu frames, the match on %llu; worst scale gap %.2e; %llu frames in "
              "the %.0f s after, %llu later ones with the scales over %.0e apart; on those, worst |V_fixed - V_double| "
              "%.2f %% of the speed",
              static_cast<unsigned long long>(f.tof_mismatch), static_cast<unsigned long long>(f.delivered),
              static_cast<unsigned long long>(f.tof_pick_split), f.worst_scale_gap,
              static_cast<unsigned long long>(f.twin_after_tof_split), kTofSplitWindowS,
              static_cast<unsigned long long>(f.twin_scales_apart), kScaleApart, 100 * f.worst_twin_after_tof_split);

  CHECK(c.bursts > 0 && c.reversals > 0 && c.standstills > 0 && c.dropped > 0);
  LONGS_EQUAL(0, f.status_mismatch);
  CHECK((f.tof_mismatch + f.tof_pick_split) * 100000 <= f.delivered);  // at most 1e-5 of the frames
  CHECK(f.twin_scales_apart * 1000 <= f.delivered);  // scales kept apart after the windows: at most 1e-3
  CHECK(f.worst_twin_after_tof_split < 0.05);
  CHECK(f.worst_scale_gap < 5e-3);
  LONGS_EQUAL(0, f.flag_errors);
  LONGS_EQUAL(0, f.unexpected_flags);
  LONGS_EQUAL(0, f.still_while_moving);
  CHECK(f.still_frames > 0);
  CHECK(f.worst_offset_error < 1e-3);
  CHECK(f.worst_heading_vs_double < 1e-7);
  CHECK(f.distance_vs_double < 1e-6);
  CHECK(f.twin_outside == 0);
  CHECK(f.worst_twin_heading < 1e-3);  // the learned offsets of the two engines differ in the last bits
  CHECK(f.heap_growth < 65536);
  // The estimator's own accuracy on this scene (pixel noise of 1 grey level
  // on 4 rows): what it measures is printed above; these bounds catch a
  // regression, not tune it.
  CHECK(v_rms < 0.05);
  CHECK(std::fabs(v_bias) < 0.01 * mean_speed);
  CHECK(std::fabs(f.distance_vs_truth) < 0.01 * f.observed_path);
}
