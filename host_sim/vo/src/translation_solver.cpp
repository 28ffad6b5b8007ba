#include "lumavel/host/vo/translation_solver.hpp"

#include <algorithm>
#include <cmath>

namespace lumavel::host::vo {
namespace {

// For camera c, the point now is A_c X + B_c t + C_c (cam0: R, I, 0;
// cam1: R_10 R, R_10, t_10). Its projection (u, v) = (Y_x / Y_z, Y_y / Y_z).
struct CameraTerms {
  cv::Matx33d A, B;
  cv::Vec3d C;
};

struct Normal {
  cv::Matx33d M = cv::Matx33d::zeros();
  cv::Vec3d b = cv::Vec3d(0, 0, 0);
};

// Adds the two linear equations of one observation in one camera,
// u Y_z - Y_x = 0 and v Y_z - Y_y = 0, weighted by f / depth so that each
// equation's residual is a reprojection error in pixels.
void add_equations(Normal& nrm, const CameraTerms& c, const cv::Vec3d& X, const cv::Point2d& n, double weight) {
  const cv::Vec3d k = c.A * X + c.C;
  const double uv[2] = {n.x, n.y};
  for (int r = 0; r < 2; ++r) {
    cv::Vec3d row;
    for (int j = 0; j < 3; ++j) row[j] = uv[r] * c.B(2, j) - c.B(r, j);
    const double rhs = -(uv[r] * k[2] - k[r]);
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) nrm.M(i, j) += weight * weight * row[i] * row[j];
      nrm.b[i] += weight * weight * row[i] * rhs;
    }
  }
}

bool solve(const Normal& nrm, cv::Vec3d& t) {
  if (std::fabs(cv::determinant(nrm.M)) < 1e-300) return false;
  t = nrm.M.solve(nrm.b, cv::DECOMP_CHOLESKY);
  return std::isfinite(t[0]) && std::isfinite(t[1]) && std::isfinite(t[2]);
}

// Largest reprojection error of the observation in the two cameras (pixels),
// and the depths the point has now (for the weights); infinite when it
// would be behind a camera.
double reprojection_px(const CameraTerms cam[2], const MotionObservation& o, const cv::Vec3d& t, const double f[2],
                       double depth[2]) {
  double worst = 0;
  for (int c = 0; c < 2; ++c) {
    const cv::Vec3d Y = cam[c].A * o.X + cam[c].B * t + cam[c].C;
    depth[c] = Y[2];
    if (!(Y[2] > 0)) return INFINITY;
    const double du = Y[0] / Y[2] - o.n[c].x, dv = Y[1] / Y[2] - o.n[c].y;
    worst = std::fmax(worst, f[c] * std::sqrt(du * du + dv * dv));
  }
  return worst;
}

}  // namespace

TranslationResult solve_translation(const std::vector<MotionObservation>& obs, const cv::Matx33d& R,
                                    const StereoRig& rig, const double f_px[2], double inlier_px,
                                    double inlier_floor_px, int min_inliers) {
  TranslationResult res;
  res.inlier.assign(obs.size(), false);
  if (obs.size() < static_cast<size_t>(min_inliers) || obs.empty()) return res;
  const CameraTerms cam[2] = {{R, cv::Matx33d::eye(), cv::Vec3d(0, 0, 0)}, {rig.R_10 * R, rig.R_10, rig.t_10}};

  auto fit = [&](const std::vector<size_t>& idx, const cv::Vec3d* depth_from, cv::Vec3d& t) {
    Normal nrm;
    for (size_t i : idx) {
      double d[2] = {obs[i].X[2], obs[i].X[2]};
      if (depth_from) reprojection_px(cam, obs[i], *depth_from, f_px, d);
      for (int c = 0; c < 2; ++c) add_equations(nrm, cam[c], obs[i].X, obs[i].n[c], f_px[c] / std::fmax(d[c], 1e-6));
    }
    return solve(nrm, t);
  };
  auto score = [&](const cv::Vec3d& t, double threshold, std::vector<uint8_t>& in, double& sq) {
    int n = 0;
    sq = 0;
    for (size_t i = 0; i < obs.size(); ++i) {
      double d[2];
      const double e = reprojection_px(cam, obs[i], t, f_px, d);
      in[i] = e < threshold;
      if (in[i]) {
        ++n;
        sq += e * e;
      }
    }
    return n;
  };

  // 1-point hypotheses: every observation (at most 100, evenly spread).
  const size_t stride = obs.size() > 100 ? (obs.size() + 99) / 100 : 1;
  int best = -1;
  double best_sq = 0;
  cv::Vec3d best_t;
  std::vector<uint8_t> in(obs.size());
  for (size_t h = 0; h < obs.size(); h += stride) {
    cv::Vec3d t;
    if (!fit({h}, nullptr, t)) continue;
    double sq;
    const int n = score(t, inlier_px, in, sq);
    if (n > best || (n == best && sq < best_sq)) {
      best = n;
      best_sq = sq;
      best_t = t;
    }
  }
  if (best < min_inliers) return res;
  // Refine: least squares on the inliers, then a tighter threshold from the
  // residuals themselves (three times their median, within [floor, max]):
  // with slow motion a wrong depth errs by a fraction of a pixel only, far
  // above the residuals of good tracks but below any fixed pixel threshold.
  cv::Vec3d t = best_t;
  double threshold = inlier_px;
  for (int pass = 0; pass < 3; ++pass) {
    std::vector<size_t> idx;
    std::vector<double> err;
    for (size_t i = 0; i < obs.size(); ++i) {
      double d[2];
      const double e = reprojection_px(cam, obs[i], t, f_px, d);
      if (e < threshold) {
        idx.push_back(i);
        err.push_back(e);
      }
    }
    if (idx.size() < static_cast<size_t>(min_inliers)) return res;
    cv::Vec3d refined;
    if (!fit(idx, &t, refined)) return res;
    t = refined;
    std::nth_element(err.begin(), err.begin() + static_cast<std::ptrdiff_t>(err.size() / 2), err.end());
    threshold = std::clamp(3 * err[err.size() / 2], inlier_floor_px, inlier_px);
  }
  double sq;
  res.inliers = score(t, threshold, res.inlier, sq);
  if (res.inliers < min_inliers) return res;
  res.ok = true;
  res.t = t;
  res.rms_px = std::sqrt(sq / res.inliers);
  res.threshold_px = threshold;
  return res;
}

}  // namespace lumavel::host::vo
