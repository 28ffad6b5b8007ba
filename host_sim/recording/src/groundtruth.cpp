#include "lumavel/host/groundtruth.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "lumavel/host/csv_table.hpp"
#include "lumavel/host/recording_layout.hpp"

namespace lumavel::host {

std::string why_implausible_position(double p_m) {
  if (std::fabs(p_m) <= layout::kGroundTruthMaxPositionM) return "";
  return format_double(p_m) + " m is beyond +-" + format_double(layout::kGroundTruthMaxPositionM) +
         " m, farther than any point on Earth: a corrupt position";
}

std::string why_implausible_speed(double v_mps) {
  if (std::fabs(v_mps) <= layout::kGroundTruthMaxSpeedMps) return "";
  return format_double(v_mps) + " m/s is beyond +-" + format_double(layout::kGroundTruthMaxSpeedMps) +
         " m/s, faster than any vehicle: a corrupt velocity";
}

std::string why_not_unit_quaternion(double norm) {
  // Against 1 -+ the tolerance, which round as 0.99 and 1.01 do: |norm - 1|
  // of a norm of 1.01 is 0.010000000000000009, and a norm at the rule's own
  // bound was refused.
  constexpr double tol = layout::kGroundTruthQuaternionNormTolerance;
  if (norm >= 1.0 - tol && norm <= 1.0 + tol) return "";
  return "is not a unit quaternion (norm " + format_double(norm) + "): its norm must be within " +
         format_double(layout::kGroundTruthQuaternionNormTolerance) + " of 1";
}

double body_forward_velocity(const GroundTruthSample& g) {
  const double n = std::sqrt(g.q[0] * g.q[0] + g.q[1] * g.q[1] + g.q[2] * g.q[2] + g.q[3] * g.q[3]);
  const double w = g.q[0] / n, x = g.q[1] / n, y = g.q[2] / n, z = g.q[3] / n;
  // x of R(q)^T v: the first column of R(q) dotted with v (body x axis in world).
  const double bx[3] = {1 - 2 * (y * y + z * z), 2 * (x * y + w * z), 2 * (x * z - w * y)};
  return bx[0] * g.v[0] + bx[1] * g.v[1] + bx[2] * g.v[2];
}

namespace {

// The longest interval interpolated across: kGroundTruthMaxHoleIntervals
// times the median one (the samples' times rise strictly).
uint64_t longest_interpolated_interval(const std::vector<GroundTruthSample>& gt) {
  if (gt.size() < 2) return 0;
  std::vector<uint64_t> dt(gt.size() - 1);
  for (size_t k = 0; k + 1 < gt.size(); ++k) dt[k] = gt[k + 1].t_ns - gt[k].t_ns;
  std::nth_element(dt.begin(), dt.begin() + static_cast<std::ptrdiff_t>(dt.size() / 2), dt.end());
  return static_cast<uint64_t>(static_cast<double>(dt[dt.size() / 2]) * layout::kGroundTruthMaxHoleIntervals);
}

}  // namespace

std::string why_velocity_is_not_the_positions_rate(const std::vector<GroundTruthSample>& gt,
                                                   const std::vector<long>& line, long& at_line) {
  bool moves = false;
  for (const GroundTruthSample& g : gt)
    for (int k = 0; k < 3; ++k) moves = moves || g.p[k] != gt.front().p[k];
  if (!moves) return "";
  const uint64_t longest = longest_interpolated_interval(gt);
  const auto stretch_ns = static_cast<uint64_t>(layout::kGroundTruthRateStretchS * 1e9);
  auto norm = [](const double a[3]) { return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); };
  double by_positions = 0, by_velocity = 0, apart = 0, worst = -1;
  size_t worst_i = 0, worst_j = 0, stretches = 0;
  double worst_dp[3] = {0, 0, 0}, worst_iv[3] = {0, 0, 0};
  for (size_t i = 0; i + 1 < gt.size();) {
    size_t j = i;
    double iv[3] = {0, 0, 0};  // the velocity integrated (trapezoids)
    while (j + 1 < gt.size() && gt[j + 1].t_ns - gt[j].t_ns <= longest && gt[j].t_ns - gt[i].t_ns < stretch_ns) {
      const double dt = static_cast<double>(gt[j + 1].t_ns - gt[j].t_ns) * 1e-9;
      for (int k = 0; k < 3; ++k) iv[k] += 0.5 * (gt[j].v[k] + gt[j + 1].v[k]) * dt;
      ++j;
    }
    if (j == i) {  // a hole after sample i: nothing known across it
      ++i;
      continue;
    }
    double dp[3], d[3];
    for (int k = 0; k < 3; ++k) {
      dp[k] = gt[j].p[k] - gt[i].p[k];
      d[k] = dp[k] - iv[k];
    }
    by_positions += norm(dp);
    by_velocity += norm(iv);
    apart += std::max(0.0, norm(d) - layout::kGroundTruthRateSlackM);
    ++stretches;
    if (norm(d) > worst) {
      worst = norm(d);
      worst_i = i;
      worst_j = j;
      std::copy(dp, dp + 3, worst_dp);
      std::copy(iv, iv + 3, worst_iv);
    }
    i = j;
  }
  const double allowed = layout::kGroundTruthRateApartShare * std::max(by_positions, by_velocity);
  if (stretches == 0 || apart <= allowed) return "";
  auto vec = [](const double a[3]) {
    return "(" + format_double(a[0]) + ", " + format_double(a[1]) + ", " + format_double(a[2]) + ") m";
  };
  at_line = line[worst_i];
  return "the velocity v_RS_R is not the rate of change of the position p_RS_R: from line " +
         std::to_string(line[worst_i]) + " to line " + std::to_string(line[worst_j]) + " (t = " +
         std::to_string(gt[worst_i].t_ns) + " .. " + std::to_string(gt[worst_j].t_ns) + " ns) the position moves " +
         vec(worst_dp) + ", the velocity integrated " + vec(worst_iv) + "; over the file's " +
         std::to_string(stretches) + " stretches of up to " + format_double(layout::kGroundTruthRateStretchS) +
         " s the positions travel " + format_double(by_positions) + " m, the velocities " +
         format_double(by_velocity) + " m, " + format_double(apart) + " m apart beyond " +
         format_double(layout::kGroundTruthRateSlackM) + " m a stretch, where at most " + format_double(layout::kGroundTruthRateApartShare) +
         " of the larger travel is allowed. V is compared with the velocity: the body origin's, in the world frame, in m/s (not zeros where "
         "it is unknown, nor the body frame's or another unit's); remove the file for a run without ground truth";
}

std::vector<double> true_forward_velocity(const std::vector<GroundTruthSample>& gt,
                                          const std::vector<uint64_t>& t_ns) {
  std::vector<double> out(t_ns.size(), std::numeric_limits<double>::quiet_NaN());
  if (gt.empty()) return out;
  const uint64_t longest = longest_interpolated_interval(gt);
  size_t j = 0;
  for (size_t i = 0; i < t_ns.size(); ++i) {
    const uint64_t t = t_ns[i];
    if (t < gt.front().t_ns || t > gt.back().t_ns) continue;
    while (j + 1 < gt.size() && gt[j + 1].t_ns < t) ++j;
    if (gt[j].t_ns == t || j + 1 == gt.size()) {
      out[i] = body_forward_velocity(gt[j]);
      continue;
    }
    const GroundTruthSample& a = gt[j];
    const GroundTruthSample& b = gt[j + 1];
    if (b.t_ns - a.t_ns > longest) continue;  // inside a hole of the ground truth: no truth
    const double f = static_cast<double>(t - a.t_ns) / static_cast<double>(b.t_ns - a.t_ns);
    out[i] = (1 - f) * body_forward_velocity(a) + f * body_forward_velocity(b);
  }
  return out;
}

}  // namespace lumavel::host
