#include "lumavel/host/calibrate.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "lumavel/host/file_camera.hpp"
#include "lumavel/host/recording_error.hpp"
#include "lumavel/host/rig.hpp"

namespace lumavel::host {
namespace {

// A column profile resampled on a uniform grid of camera-relative yaw.
struct Profile {
  std::vector<double> v;  // brightness / mean, on the grid
};

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

// Normalised correlation of a[i] with b[i + shift] over the central part.
double correlation(const Profile& a, const Profile& b, int shift, int margin) {
  double sa = 0, sb = 0, saa = 0, sbb = 0, sab = 0;
  int n = 0;
  for (int i = margin; i + margin < static_cast<int>(a.v.size()); ++i) {
    const double x = a.v[static_cast<size_t>(i)], y = b.v[static_cast<size_t>(i + shift)];
    sa += x;
    sb += y;
    saa += x * x;
    sbb += y * y;
    sab += x * y;
    ++n;
  }
  const double cov = sab - sa * sb / n, va = saa - sa * sa / n, vb = sbb - sb * sb / n;
  return va > 0 && vb > 0 ? cov / std::sqrt(va * vb) : 0;
}

struct Match {
  double corr = -1, shift = 0;  // shift in grid steps, sub-step
  bool interior = false;
};

Match best_shift(const Profile& a, const Profile& b, int max_shift) {
  std::vector<double> c(static_cast<size_t>(2 * max_shift + 1));
  for (int s = -max_shift; s <= max_shift; ++s) c[static_cast<size_t>(s + max_shift)] = correlation(a, b, s, max_shift);
  const size_t k = static_cast<size_t>(std::max_element(c.begin(), c.end()) - c.begin());
  Match m;
  m.corr = c[k];
  m.shift = static_cast<double>(k) - max_shift;
  m.interior = k > 0 && k + 1 < c.size();
  if (m.interior) {  // parabola through the peak and its neighbours
    const double l = c[k - 1], r = c[k + 1], d = l - 2 * c[k] + r;
    if (d < 0) m.shift += 0.5 * (l - r) / d;
  }
  return m;
}

}  // namespace

Calibration calibrate_misalignment(const Recording& rec, const CalibrationOptions& opt) {
  const int width = std::min(opt.width, rec.cam[0].width);
  const int height = std::min(rec.cam[0].height, 120);
  EstimatorSettings s = derive_settings(rec, {width, height});
  const std::vector<double> yaw0 = column_yaws(s, 0), yaw1 = column_yaws(s, 1);
  // Grid: a tenth of a column over the part of the view both cameras cover.
  const double lo = std::max(*std::min_element(yaw0.begin(), yaw0.end()), *std::min_element(yaw1.begin(), yaw1.end()));
  const double hi = std::min(*std::max_element(yaw0.begin(), yaw0.end()), *std::max_element(yaw1.begin(), yaw1.end()));
  Grid g;
  g.step = (hi - lo) / width / 10;
  g.n = static_cast<int>((hi - lo) / g.step);
  g.start = lo;
  const int max_shift = static_cast<int>(opt.max_shift_deg * M_PI / 180 / g.step);
  if (2 * max_shift + 10 >= g.n) throw std::runtime_error("the view is too narrow for the shift search");

  // Profiles and gyro headings at every frame.
  FileStereoCamera camera(rec, width, height);
  std::vector<Profile> p0, p1;
  std::vector<uint64_t> times;
  std::vector<uint8_t> b0(static_cast<size_t>(width * height)), b1(b0.size());
  hal::StereoImage img{0, {b0.data(), b1.data()}, 0, 0};
  for (;;) {
    const hal::CaptureStatus st = camera.capture(img);
    if (st == hal::CaptureStatus::kEnd) break;
    if (st == hal::CaptureStatus::kError) throw RecordingError(camera.error());
    std::vector<double> c0(static_cast<size_t>(width)), c1(c0.size());
    for (int y = 0; y < height; ++y)
      for (int u = 0; u < width; ++u) {
        c0[static_cast<size_t>(u)] += b0[static_cast<size_t>(y * width + u)];
        c1[static_cast<size_t>(u)] += b1[static_cast<size_t>(y * width + u)];
      }
    p0.push_back(resample(c0, yaw0, g));
    p1.push_back(resample(c1, yaw1, g));
    times.push_back(img.t_ns);
  }
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

  Calibration out;
  std::vector<double> samples;
  for (size_t i = 0; i + 1 < p0.size(); ++i) {
    // Standing still: every lag matches; such frames say nothing.
    if (correlation(p0[i], p0[i + 1], 0, max_shift) > 0.99995) continue;
    ++out.candidates;
    double best_corr = -1, best_delta = 0;
    bool ok = false;
    for (size_t j = i + 1; j < p0.size() && j <= i + static_cast<size_t>(opt.max_lag); ++j) {
      const double dtheta = heading[j] - heading[i];
      // cam1 at i and cam0 at j (moving towards cam1's side) ...
      const Match a = best_shift(p1[i], p0[j], max_shift);
      if (a.corr > best_corr) {
        best_corr = a.corr;
        best_delta = a.shift * g.step + dtheta;
        ok = a.interior;
      }
      // ... or cam0 at i and cam1 at j (moving the other way).
      const Match b = best_shift(p0[i], p1[j], max_shift);
      if (b.corr > best_corr) {
        best_corr = b.corr;
        best_delta = -(b.shift * g.step) - dtheta;
        ok = b.interior;
      }
    }
    if (ok && best_corr >= opt.min_correlation) samples.push_back(best_delta);
  }
  if (samples.empty())
    throw std::runtime_error("no frame pair registered (does the rig move past a textured scene?)");
  std::sort(samples.begin(), samples.end());
  const double median = samples[samples.size() / 2];
  std::vector<double> dev;
  for (double x : samples) dev.push_back(std::fabs(x - median));
  std::sort(dev.begin(), dev.end());
  out.misalignment = median;
  out.uncertainty = 1.4826 * dev[dev.size() / 2] * 1.2533 / std::sqrt(static_cast<double>(samples.size()));
  out.samples = samples.size();
  return out;
}

}  // namespace lumavel::host
