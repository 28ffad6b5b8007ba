#include "lumavel/host/calibrate.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <stdexcept>
#include <vector>

#include "lumavel/host/file_camera.hpp"
#include "lumavel/host/motion_direction.hpp"
#include "lumavel/host/path_check.hpp"
#include "lumavel/host/recording_error.hpp"
#include "lumavel/host/rig.hpp"
#include "lumavel/host/rig_settings_check.hpp"

namespace lumavel::host {
namespace {

// A column profile resampled on a uniform grid of camera-relative yaw.
struct Profile {
  std::vector<double> v;  // brightness / mean, on the grid
};

// Windows across the common view for the zero-translation regression.
// (12 measured best on a 3.5 m/s photo-wall pass misaligned by -3..3 deg:
// 6 or 8 windows left up to 0.12 deg of bias at 3 deg, 16 were noisier.)
constexpr int kWindows = 12;
// Lags registered around the best one: more lags, more samples of the same
// intercept.
constexpr size_t kLagsBefore = 1, kLagsAfter = 2;
// Registered windows a frame needs for the regression.
constexpr int kMinWindows = 6;
// Frames with every window registered needed to use only those.
constexpr size_t kMinCompleteFrames = 30;
// Frames per block for the uncertainty.
constexpr size_t kUncertaintyBlock = 20;
// The registrations' slope against the gyro's heading change refused (see
// calibrate_misalignment): a gyro right leaves none, a sign-flipped one 2.
constexpr double kMaxTurnSlope = 0.5;
constexpr double kTurnSlopeSigmas = 5;
// Frames either side whose translation-field shapes are averaged.
constexpr size_t kShapeHalfSpan = 15;
// The registration's resolution floor, in working columns, added in
// quadrature to the spread over blocks: the spread alone said 0.04 deg where
// the error was 0.36 deg at 40 columns (issue 15). Measured on robustness_wall
// and paper_sim_misaligned at 20, 40, 80 and 160 columns, misaligned by -3..3
// deg (40 renders of 4 s): with 1/6 of a column the truth is within 2 sigma
// in 34 of 40, and in every one of the 9 whose uncertainty is at most 0.1 deg
// (all at 160 columns); the 6 outside are at 20 and 40 columns, where the
// floor alone exceeds 0.1 deg (1/7 left a 40-column estimate at 2.02 sigma).
// Repeat with host_sim/calibrate/study/uncertainty_study.sh.
constexpr double kResolutionFloorColumns = 1.0 / 6;

struct Grid {
  double start = 0, step = 0;
  int n = 0;
};

// Camera-relative yaw (body yaw minus the optical axis) of each column centre.
std::vector<double> column_yaws(const EstimatorSettings& s, int cam) {
  const CameraModel& c = s.cam[cam];
  std::vector<double> out(static_cast<size_t>(s.width));
  for (int u = 0; u < s.width; ++u) {
    const double yaw = c.edges.empty() ? c.axis_yaw + c.u_sign * std::atan((u - c.cu) / c.fu)
                                       : (c.edges[static_cast<size_t>(u)] + c.edges[static_cast<size_t>(u) + 1]) / 2;
    out[static_cast<size_t>(u)] = yaw - c.axis_yaw;
  }
  return out;
}

Profile resample(const std::vector<double>& sums, const std::vector<double>& yaw, const Grid& g) {
  // yaw runs monotonically (either way); interpolate linearly.
  std::vector<std::pair<double, double>> pts;
  double mean = 0;
  for (size_t u = 0; u < sums.size(); ++u) mean += sums[u];
  mean /= static_cast<double>(sums.size());
  for (size_t u = 0; u < sums.size(); ++u) pts.emplace_back(yaw[u], mean > 0 ? sums[u] / mean : 0);
  std::sort(pts.begin(), pts.end());
  Profile p;
  p.v.resize(static_cast<size_t>(g.n));
  size_t k = 0;
  for (int i = 0; i < g.n; ++i) {
    const double a = g.start + i * g.step;
    while (k + 2 < pts.size() && pts[k + 1].first < a) ++k;
    const double t = (a - pts[k].first) / (pts[k + 1].first - pts[k].first);
    p.v[static_cast<size_t>(i)] = pts[k].second + std::clamp(t, 0.0, 1.0) * (pts[k + 1].second - pts[k].second);
  }
  return p;
}

// Hann weights over n grid points: a tapered window keeps features that
// cross its edge from pulling its shift.
std::vector<double> hann(int n) {
  std::vector<double> w(static_cast<size_t>(n));
  for (int k = 0; k < n; ++k) {
    const double s = std::sin(M_PI * (k + 0.5) / n);
    w[static_cast<size_t>(k)] = s * s;
  }
  return w;
}

// Normalised correlation of a[i] with b[i + shift] for i in [lo, hi),
// weighted by taper[i - lo] when a taper is given (hi - lo values).
double correlation(const Profile& a, const Profile& b, int shift, int lo, int hi, const std::vector<double>* taper) {
  double sw = 0, sa = 0, sb = 0, saa = 0, sbb = 0, sab = 0;
  for (int i = lo; i < hi; ++i) {
    const double x = a.v[static_cast<size_t>(i)], y = b.v[static_cast<size_t>(i + shift)];
    const double w = taper ? (*taper)[static_cast<size_t>(i - lo)] : 1.0;
    sw += w;
    sa += w * x;
    sb += w * y;
    saa += w * x * x;
    sbb += w * y * y;
    sab += w * x * y;
  }
  const double cov = sab - sa * sb / sw, va = saa - sa * sa / sw, vb = sbb - sb * sb / sw;
  return va > 0 && vb > 0 ? cov / std::sqrt(va * vb) : 0;
}

struct Match {
  double corr = -1, shift = 0;  // shift in grid steps, sub-step
  bool interior = false;
};

// Best shift of b against a over grid points [lo, hi), searched in
// [s_lo, s_hi] (the caller keeps lo + s_lo >= 0 and hi + s_hi <= size).
// With a stride, coarse to fine: over the whole view the correlation peak
// is about a column (10 grid steps) wide, so every third shift finds it and
// its neighbourhood refines it. Windows need every shift (side lobes).
Match best_shift(const Profile& a, const Profile& b, int lo, int hi, int s_lo, int s_hi, int stride,
                 const std::vector<double>* taper) {
  std::vector<double> c(static_cast<size_t>(s_hi - s_lo + 1), -2.0);
  auto at = [&](int s) -> double& { return c[static_cast<size_t>(s - s_lo)]; };
  int best = s_lo;
  for (int s = s_lo; s <= s_hi; s += stride) {
    at(s) = correlation(a, b, s, lo, hi, taper);
    if (at(s) > at(best)) best = s;
  }
  const int coarse = best;
  for (int s = std::max(s_lo, coarse - stride); s <= std::min(s_hi, coarse + stride); ++s) {
    if (at(s) < -1.5) at(s) = correlation(a, b, s, lo, hi, taper);
    if (at(s) > at(best)) best = s;
  }
  Match m;
  m.corr = at(best);
  m.shift = best;
  m.interior = best > s_lo && best < s_hi;
  if (m.interior) {  // parabola through the peak and its neighbours
    for (int s : {best - 1, best + 1})
      if (at(s) < -1.5) at(s) = correlation(a, b, s, lo, hi, taper);
    const double l = at(best - 1), r = at(best + 1), d = l - 2 * at(best) + r;
    if (d < 0) m.shift += 0.5 * (l - r) / d;
  }
  return m;
}

Match best_shift(const Profile& a, const Profile& b, int max_shift) {
  return best_shift(a, b, max_shift, static_cast<int>(a.v.size()) - max_shift, -max_shift, max_shift, 3, nullptr);
}

// Where the two cameras stood at the same place the images differ by a pure
// rotation, the misalignment; a frame off, the translation adds a shift that
// depends on each column's depth and angle. Per window c and lag k:
//   a_k(c) = delta + r_k g(c)
// (r_k: distance from the place, g: the translation field's shape: cos^2 of
// the angle on a plane parallel to the path). delta is the intercept of a_k
// regressed on g: the shift extrapolated to zero translation. g is measured
// as a2 - a1 but that is too noisy to regress on (the slope would be diluted
// and the intercept pulled towards the mean shift), so its shape is averaged
// over neighbouring frames, where the scene's depth structure is much the
// same.
struct FrameShifts {
  size_t frame = 0;
  std::vector<std::vector<double>> a;  // per lag (increasing), per window
  // Per lag: the gyro's heading change the lag's shifts were corrected by,
  // with the sign it enters them with (a gyro off by a factor k puts
  // (k - 1) times this into them).
  std::vector<double> turn;
};

// Intercept of y on x (least squares) over the windows where both are
// known (not NaN); false with fewer than kMinWindows or when x does not vary.
bool intercept(const std::vector<double>& x, const std::vector<double>& y, double& out) {
  double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (size_t c = 0; c < x.size(); ++c) {
    if (std::isnan(x[c]) || std::isnan(y[c])) continue;
    n += 1;
    sx += x[c];
    sy += y[c];
    sxx += x[c] * x[c];
    sxy += x[c] * y[c];
  }
  if (n < kMinWindows) return false;
  const double var = sxx - sx * sx / n;
  if (!(var > 1e-12 * sxx)) return false;
  const double slope = (sxy - sx * sy / n) / var;
  out = (sy - slope * sx) / n;
  return std::isfinite(out);
}

// The translation field's shape per window (NaN where a window did not
// register), mean 1; empty when the extreme lags barely differ.
std::vector<double> field_shape(const FrameShifts& f) {
  std::vector<double> g(f.a[0].size());
  double mean = 0;
  int n = 0;
  for (size_t c = 0; c < g.size(); ++c) {
    g[c] = f.a.back()[c] - f.a.front()[c];
    if (!std::isnan(g[c])) mean += g[c], ++n;
  }
  if (n < kMinWindows) return {};
  mean /= n;
  if (std::fabs(mean) < 1e-6) return {};
  for (double& x : g) x /= mean;
  return g;
}

// Radians as degrees for messages, %g.
std::string deg(double rad) {
  char b[32];
  std::snprintf(b, sizeof b, "%g", rad * 180 / M_PI);
  return b;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

// One misalignment sample per frame: the intercepts at its lags with the
// shape averaged over frames within `half_span` of it, averaged; into
// `turns`, each sample's gyro heading change (FrameShifts::turn) averaged
// over the same lags.
std::vector<double> zero_translation_samples(const std::vector<FrameShifts>& frames, size_t half_span,
                                             std::vector<double>& turns) {
  std::vector<std::vector<double>> shapes;
  for (const FrameShifts& f : frames) shapes.push_back(field_shape(f));
  std::vector<double> out;
  for (size_t i = 0; i < frames.size(); ++i) {
    std::vector<double> shape(static_cast<size_t>(kWindows), 0.0);
    std::vector<int> used(shape.size(), 0);
    for (size_t k = 0; k < frames.size(); ++k) {
      const size_t d = frames[k].frame > frames[i].frame ? frames[k].frame - frames[i].frame
                                                         : frames[i].frame - frames[k].frame;
      if (d > half_span || shapes[k].empty()) continue;
      for (size_t c = 0; c < shape.size(); ++c)
        if (!std::isnan(shapes[k][c])) shape[c] += shapes[k][c], ++used[c];
    }
    for (size_t c = 0; c < shape.size(); ++c) shape[c] = used[c] >= 3 ? shape[c] / used[c] : std::nan("");
    double sum = 0, turn = 0;
    size_t n = 0;
    for (size_t l = 0; l < frames[i].a.size(); ++l) {
      double d = 0;
      if (intercept(shape, frames[i].a[l], d)) sum += d, turn += frames[i].turn[l], ++n;
    }
    if (n > 0) {
      out.push_back(sum / static_cast<double>(n));
      turns.push_back(turn / static_cast<double>(n));
    }
  }
  return out;
}

// Least-squares slope of y on x over blocks of `block` neighbouring samples
// (x their mean, y their median: neighbouring frames see the same scene, so
// their errors are alike, and a block is one independent sample, as for the
// uncertainty), its 1-sigma error, and the spread (standard deviation) of
// the blocks' x. Zero slope and sigma with fewer than 4 blocks or when x does
// not vary.
struct TurnSlope {
  double slope = 0, sigma = 0, spread = 0;
  size_t blocks = 0;
};

TurnSlope turn_slope(const std::vector<double>& x, const std::vector<double>& y, size_t block) {
  std::vector<double> bx, by;
  for (size_t b = 0; b + block <= x.size(); b += block) {
    double sum = 0;
    for (size_t i = b; i < b + block; ++i) sum += x[i];
    bx.push_back(sum / static_cast<double>(block));
    by.push_back(median({y.begin() + static_cast<std::ptrdiff_t>(b), y.begin() + static_cast<std::ptrdiff_t>(b + block)}));
  }
  TurnSlope out;
  out.blocks = bx.size();
  if (bx.size() < 4) return out;
  const double n = static_cast<double>(bx.size());
  double mx = 0, my = 0;
  for (size_t i = 0; i < bx.size(); ++i) mx += bx[i] / n, my += by[i] / n;
  double vx = 0, cxy = 0, vy = 0;
  for (size_t i = 0; i < bx.size(); ++i) {
    vx += (bx[i] - mx) * (bx[i] - mx);
    cxy += (bx[i] - mx) * (by[i] - my);
    vy += (by[i] - my) * (by[i] - my);
  }
  out.spread = std::sqrt(vx / n);
  if (!(vx > 0)) return out;
  out.slope = cxy / vx;
  out.sigma = std::sqrt(std::max(vy - out.slope * cxy, 0.0) / (n - 2) / vx);
  return out;
}

}  // namespace

Calibration calibrate_misalignment(const Recording& rec, const CalibrationOptions& opt) {
  const int width = std::min(opt.width, rec.cam[0].width);
  const int height = std::min(rec.cam[0].height, 120);
  EstimatorSettings s = derive_settings(rec, {width, height});
  // The rules `run` reads a rig by: what the core cannot take is refused here
  // too, naming the file (a principal point of 1e6 px, a 40 m baseline).
  check_rig_settings(rec, s);
  const std::vector<double> yaw0 = column_yaws(s, 0), yaw1 = column_yaws(s, 1);
  // Grid: a tenth of a column over the part of the view both cameras cover.
  const double lo = std::max(*std::min_element(yaw0.begin(), yaw0.end()), *std::min_element(yaw1.begin(), yaw1.end()));
  const double hi = std::min(*std::max_element(yaw0.begin(), yaw0.end()), *std::max_element(yaw1.begin(), yaw1.end()));
  Grid g;
  g.step = (hi - lo) / width / 10;
  g.start = lo;
  // Checked in double before any cast: a view a few ulps wide would
  // overflow an int.
  const double shift_steps = opt.max_shift_deg * M_PI / 180 / g.step;
  if (!(g.step > 0) || !(2 * shift_steps + 10 < 10.0 * width))
    throw RecordingError(
        shown_path(rec.root) + "/cam0/sensor.yaml and cam1/sensor.yaml: the view both cameras share is " +
        deg(hi - lo) + " deg wide, too narrow for the +-" + deg(opt.max_shift_deg * M_PI / 180) + " deg shift search");
  g.n = static_cast<int>((hi - lo) / g.step);
  const int max_shift = static_cast<int>(shift_steps);
  // Below one step of the grid the search was +-0 steps: nothing registered,
  // and the error blamed the scene ("does the rig move past a textured scene?").
  if (max_shift < 1)
    throw std::runtime_error("--max-shift " + deg(opt.max_shift_deg * M_PI / 180) +
                             " deg is less than one step of the registration grid (" + deg(g.step) + " deg at " +
                             std::to_string(width) + " columns): nothing would be searched; give at least " +
                             deg(g.step) + " deg, and more than the misalignment");

  // Profiles and gyro headings at every frame.
  FileStereoCamera camera(rec, width, height);
  std::vector<Profile> p0, p1;
  std::vector<uint64_t> times;
  // Frames where both cameras delivered the same, textured image (the
  // estimator's NO_STEREO): no stereo difference, nothing to register; were
  // they registered, a camera would be matched against itself at another
  // time (was: exit 0 and a misalignment to send to a board).
  std::vector<bool> same_image;
  std::vector<uint8_t> b0(static_cast<size_t>(width * height)), b1(b0.size());
  hal::StereoImage img{0, {b0.data(), b1.data()}, 0, 0};
  MotionDirectionCheck motion(width, height, u_sign_of(rec.cam[0]), u_sign_of(rec.cam[1]));
  for (;;) {
    const hal::CaptureStatus st = camera.capture(img);
    if (st == hal::CaptureStatus::kEnd) break;
    if (st == hal::CaptureStatus::kError) throw RecordingError(camera.error());
    if (opt.progress) opt.progress("reading frames", times.size(), rec.frames.size());
    std::vector<double> c0(static_cast<size_t>(width)), c1(c0.size());
    for (int y = 0; y < height; ++y)
      for (int u = 0; u < width; ++u) {
        c0[static_cast<size_t>(u)] += b0[static_cast<size_t>(y * width + u)];
        c1[static_cast<size_t>(u)] += b1[static_cast<size_t>(y * width + u)];
      }
    same_image.push_back(b0 == b1 && std::any_of(b0.begin(), b0.end(), [&](uint8_t v) { return v != b0[0]; }));
    motion.add(b0.data(), b1.data());
    p0.push_back(resample(c0, yaw0, g));
    p1.push_back(resample(c1, yaw1, g));
    times.push_back(img.t_ns);
  }
  // A mirrored camera's images move against the other's: registering them
  // gave a misalignment to send to a board, exit 0.
  if (motion.mirrored())
    throw RecordingError(shown_path(rec.root) + ": " +
                         opposite_motion_text(motion.opposite(), motion.same() + motion.opposite(), rec.root) +
                         "; they cannot be registered");
  std::vector<double> heading(times.size(), 0.0);
  {
    size_t k = 0;
    double angle = 0, t_prev = 0, r_prev = 0;
    bool have = false;
    for (size_t f = 0; f < times.size(); ++f) {
      while (k < rec.imu_samples.size() && rec.imu_samples[k].t_ns <= times[f]) {
        const double t = static_cast<double>(rec.imu_samples[k].t_ns) * 1e-9, r = body_yaw_rate(rec.imu, rec.imu_samples[k]);
        if (have) angle += (r + r_prev) / 2 * (t - t_prev);
        t_prev = t;
        r_prev = r;
        have = true;
        ++k;
      }
      heading[f] = angle;
    }
  }

  // Windows for the zero-translation regression, and how far a window's
  // shift may stray from the whole view's (the translation field varies by
  // a fraction of a frame's motion across the view).
  const int lo_all = max_shift, hi_all = g.n - max_shift;
  // Tapered windows overlapping by half.
  const int window_step = (hi_all - lo_all) / (kWindows + 1), window_len = 2 * window_step;
  const std::vector<double> taper = hann(window_len);
  const int window_slack = 30;
  Calibration out;
  out.width = width;
  out.height = height;
  std::vector<FrameShifts> shifts;
  size_t at_edge = 0;  // frames whose best match, a good one, lay at the end of the search
  size_t same = 0;     // frames both cameras saw as one image
  for (size_t i = 0; i + 1 < p0.size(); ++i) {
    if (opt.progress) opt.progress("registering", i, p0.size() - 1);
    if (same_image[i]) {
      ++same;
      continue;
    }
    // Standing still: every lag matches; such frames say nothing.
    if (correlation(p0[i], p0[i + 1], 0, lo_all, hi_all, nullptr) > 0.99995) continue;
    ++out.candidates;
    // Whole-view registration at every lag and both directions: cam1 at i
    // with cam0 at j (moving towards cam1's side), or cam0 at i with cam1 at
    // j (moving the other way). Lag 0 is kept as a second lag only.
    const size_t last = std::min(p0.size() - 1, i + static_cast<size_t>(opt.max_lag));
    std::vector<Match> fwd, bwd;
    for (size_t j = i; j <= last; ++j) {
      if (same_image[j]) {  // no lag to a frame with one image for both cameras
        fwd.push_back(Match{});
        bwd.push_back(Match{});
        continue;
      }
      fwd.push_back(best_shift(p1[i], p0[j], max_shift));
      bwd.push_back(best_shift(p0[i], p1[j], max_shift));
    }
    int dir = 0;
    size_t lag = 0;
    double best_corr = -1;
    for (size_t l = 1; l < fwd.size(); ++l) {
      if (fwd[l].corr > best_corr) best_corr = fwd[l].corr, lag = l, dir = +1;
      if (bwd[l].corr > best_corr) best_corr = bwd[l].corr, lag = l, dir = -1;
    }
    const std::vector<Match>& m = dir > 0 ? fwd : bwd;
    if (lag != 0 && !m[lag].interior && best_corr >= opt.min_correlation) ++at_edge;
    if (lag == 0 || !m[lag].interior || best_corr < opt.min_correlation) continue;
    // Lags around the best one, on both sides of the place.
    const Profile& before = dir > 0 ? p1[i] : p0[i];
    FrameShifts fs;
    fs.frame = i;
    for (size_t l = lag > kLagsBefore ? lag - kLagsBefore : 0; l <= lag + kLagsAfter && l < m.size(); ++l) {
      if (!m[l].interior || m[l].corr < opt.min_correlation) continue;
      const size_t j = i + l;
      const Profile& after = dir > 0 ? p0[j] : p1[j];
      const int centre = static_cast<int>(std::lround(m[l].shift));
      const double dtheta = heading[j] - heading[i];
      std::vector<double> a;
      for (int w = 0; w < kWindows; ++w) {
        const int w_lo = lo_all + w * window_step, w_hi = w_lo + window_len;
        const Match wm = best_shift(before, after, w_lo, w_hi, std::max(centre - window_slack, -w_lo),
                                    std::min(centre + window_slack, g.n - w_hi), 1, &taper);
        // The misalignment this window says, were the translation zero
        // (NaN: the window did not register, e.g. near clutter or no texture).
        const bool ok = wm.interior && wm.corr >= opt.min_correlation;
        a.push_back(!ok ? std::nan("") : dir > 0 ? wm.shift * g.step + dtheta : -(wm.shift * g.step) - dtheta);
      }
      fs.a.push_back(std::move(a));
      fs.turn.push_back(dir > 0 ? dtheta : -dtheta);
    }
    if (fs.a.size() >= 2) shifts.push_back(std::move(fs));
  }
  // Lags where every window registered are the cleanest; partial ones are
  // used only when too few frames have two clean lags (clutter, sparse
  // texture).
  std::vector<FrameShifts> complete;
  for (const FrameShifts& f : shifts) {
    FrameShifts c{f.frame, {}, {}};
    for (size_t l = 0; l < f.a.size(); ++l)
      if (std::none_of(f.a[l].begin(), f.a[l].end(), [](double x) { return std::isnan(x); })) {
        c.a.push_back(f.a[l]);
        c.turn.push_back(f.turn[l]);
      }
    if (c.a.size() >= 2) complete.push_back(std::move(c));
  }
  if (complete.size() >= kMinCompleteFrames) shifts.swap(complete);
  std::vector<double> turns;
  const std::vector<double> samples = zero_translation_samples(shifts, kShapeHalfSpan, turns);
  // A misalignment beyond --max-shift puts every best match at the end of the
  // search, where it does not count: that was said as "does the rig move past
  // a textured scene?", blaming the scene for a search too narrow.
  if (samples.empty() && at_edge > 0)
    throw std::runtime_error(rec.root + ": no frame pair registered: " + std::to_string(at_edge) + " of " +
                             std::to_string(out.candidates) + " frames matched well only at the end of the +-" +
                             deg(opt.max_shift_deg * M_PI / 180) + " deg searched (--max-shift): is the misalignment larger?");
  // One frame has no later one to be matched against (was: "does the rig
  // move past a textured scene?", blaming the scene).
  if (p0.size() < 2)
    throw std::runtime_error(rec.root + ": no frame pair registered: " + rec.root +
                             "/cam0/data.csv has one frame, and each frame is registered against later ones (record a "
                             "pass past a textured scene)");
  out.same_image = same;
  if (samples.empty() && same > 0)
    throw std::runtime_error(rec.root + ": no frame pair registered: cam0 and cam1 delivered the same image on " +
                             std::to_string(same) + " of " + std::to_string(p0.size() - 1) +
                             " frames (no stereo difference to register: one camera's images in both folders?)");
  // The frames read and their span: a recording too short for one camera to
  // reach where the other stood (3 frames, 33 ms) is told by them.
  if (samples.empty()) {
    char span[160];
    std::snprintf(span, sizeof span, " in its %zu frames over %.3f s", times.size(),
                  static_cast<double>(times.back() - times.front()) * 1e-9);
    throw std::runtime_error(rec.root + ": no frame pair registered" + span +
                             " (does the rig move past a textured scene, for longer than one camera takes to reach "
                             "where the other stood?)");
  }
  out.misalignment = median(samples);
  // The search covers +-max_shift_deg: a median outside it (the gyro's
  // heading change dominating the registrations) is no answer.
  if (!(std::fabs(out.misalignment) <= opt.max_shift_deg * M_PI / 180))
    throw std::runtime_error("the registrations give " + deg(out.misalignment) + " deg, outside the +-" +
                             deg(opt.max_shift_deg * M_PI / 180) + " deg searched (--max-shift): no misalignment explains them (a gyro that does not "
                             "match the images?)");
  // The misalignment is one angle, whatever the rig turned between the
  // frames registered; a gyro that does not match the images (its sign
  // flipped, its T_BS upside down, a scale off) leaves (k - 1) times the
  // heading change in every registration. Where the turns differ (a pass
  // partly straight, partly turning) the registrations then follow them, and
  // their median was one of them: a sign-flipped gyro on gyro_turning
  // (straight, then a 4 m arc) gave -1.49 +- 0.06 deg for a true 0.80, exit
  // 0, and a board command. Refused where the registrations follow the
  // gyro's turn by more than kMaxTurnSlope, at kTurnSlopeSigmas over blocks
  // of frames. Measured on that pass (19 blocks): 0.03 +- 0.04 with the
  // gyro right, 1.79 +- 0.10 flipped; a straight wall pass whose gyro says
  // 1 rad/s after its first 0.4 s, 0.91 +- 0.16 (8 blocks).
  if (const TurnSlope ts = turn_slope(turns, samples, kUncertaintyBlock);
      std::fabs(ts.slope) > kMaxTurnSlope && std::fabs(ts.slope) > kTurnSlopeSigmas * ts.sigma) {
    char b[512];
    std::snprintf(b, sizeof b,
                  "/imu0/data.csv: the registrations follow the gyro's heading change between the frames registered: "
                  "%.2f +- %.2f deg of misalignment per degree it turned (%zu blocks of %zu frames, their turns "
                  "spread %.2f deg), where the misalignment is one angle whatever the turn (refused beyond %.1f, at "
                  "%.0f sigma): the gyro does not match the images (its sign, its units, or imu0/sensor.yaml's T_BS?)",
                  ts.slope, ts.sigma, ts.blocks, kUncertaintyBlock, ts.spread * 180 / M_PI, kMaxTurnSlope,
                  kTurnSlopeSigmas);
    throw RecordingError(shown_path(rec.root) + b);
  }
  // Neighbouring frames see the same scene, so their errors are alike: the
  // spread of medians over blocks of frames, not of single frames, gives
  // the uncertainty (1 sigma; 1.4826 MAD is sigma, 1.2533 sigma/sqrt(n) is
  // the median's).
  std::vector<double> blocks;
  for (size_t b = 0; b + kUncertaintyBlock <= samples.size(); b += kUncertaintyBlock)
    blocks.push_back(median({samples.begin() + static_cast<std::ptrdiff_t>(b),
                             samples.begin() + static_cast<std::ptrdiff_t>(b + kUncertaintyBlock)}));
  // Short recordings (fewer than 3 blocks): the frames' own spread, counted
  // as the whole blocks they fill, at least one, not as independent frames
  // (8 neighbouring frames of a 0.13 s pass said +-0.08 deg and suggested
  // the value for a board).
  double independent = static_cast<double>(blocks.size());
  if (blocks.size() < 3) {
    blocks = samples;
    independent = std::max(1.0, std::floor(static_cast<double>(samples.size()) / kUncertaintyBlock));
  }
  std::vector<double> dev;
  for (double x : blocks) dev.push_back(std::fabs(x - out.misalignment));
  const double spread = 1.4826 * median(dev) * 1.2533 / std::sqrt(independent);
  const double column = g.step * 10;  // one working column of the shared view, rad
  out.uncertainty = std::hypot(spread, kResolutionFloorColumns * column);
  out.samples = samples.size();
  return out;
}

}  // namespace lumavel::host
