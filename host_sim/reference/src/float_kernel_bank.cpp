// Twin of firmware/core/src/kernel_bank.cpp (the band itself: float_column_band.cpp).
#include "lumavel/host/float_kernel_bank.hpp"

#include <algorithm>
#include <cmath>

#include "lumavel/core/estimator_params.hpp"

namespace lumavel::host {
namespace {

constexpr int kSimpsonIntervals = params::kKernelSimpsonIntervals;

// Simpson's weights 1, 4, 2, 4, ..., 2, 4, 1, as kernel_bank.cpp has them.
constexpr double simpson_weight(int j) { return j == 0 || j == kSimpsonIntervals ? 1 : (j % 2 == 1 ? 4 : 2); }

// phi_n(s) = (-1)^n He_n(s) exp(-s^2/2), probabilists' Hermite polynomials,
// zero beyond the kernels' cut-off.
double gaussian_derivative(int n, double s) {
  if (std::fabs(s) > params::kKernelCutoffSigma) return 0;
  const double s2 = s * s;
  const double he[7] = {1, s, s2 - 1, s2 * s - 3 * s, s2 * s2 - 6 * s2 + 3,
                        s2 * s2 * s - 10 * s2 * s + 15 * s, s2 * s2 * s2 - 15 * s2 * s2 + 45 * s2 - 15};
  const double v = he[n] * std::exp(-s * s / 2);
  return n % 2 == 0 ? v : -v;
}

// The lens's edges where the camera model has them, else the pinhole's.
Eigen::VectorXd column_edge_yaws(const CameraModel& c, int width) {
  Eigen::VectorXd e(width + 1);
  if (!c.edges.empty()) {
    for (int u = 0; u <= width; ++u) e[u] = c.edges[static_cast<size_t>(u)];
    return e;
  }
  for (int u = 0; u <= width; ++u) e[u] = c.axis_yaw + c.u_sign * std::atan((u - 0.5 - c.cu) / c.fu);
  return e;
}

void integrate(const Eigen::VectorXd& edges, double centre, const KernelModel& k,
               Eigen::VectorXd& kk, Eigen::VectorXd& dd, Eigen::VectorXd& tt) {
  const int width = static_cast<int>(edges.size()) - 1;
  kk.resize(width);
  dd.resize(width);
  tt.resize(width);
  for (int u = 0; u < width; ++u) {
    const double lo = edges[u], hi = edges[u + 1];
    double ak = 0, ad = 0, at = 0;
    for (int j = 0; j <= kSimpsonIntervals; ++j) {
      const double psi = lo + (hi - lo) * j / kSimpsonIntervals;
      const double s = (psi - centre) / k.sigma;
      const double wj = simpson_weight(j);
      ak += wj * gaussian_derivative(k.order, s);
      ad += wj * gaussian_derivative(k.order + 1, s);
      at += wj * gaussian_derivative(k.order + 3, s);
    }
    const double ds = std::fabs(hi - lo) / k.sigma;
    kk[u] = ak * ds / (3 * kSimpsonIntervals);
    dd[u] = -ad * ds / (3 * kSimpsonIntervals);
    tt[u] = -at * ds / (3 * kSimpsonIntervals);
  }
}

void build_kernel(const EstimatorSettings& s, const Eigen::VectorXd (&edges)[2], const FloatColumnBand& band,
                  double centre, const KernelModel& k, bool unit_l1, Eigen::VectorXd* kout[2],
                  Eigen::VectorXd* dout[2], Eigen::VectorXd* tout[2]) {
  for (int i = 0; i < 2; ++i) {
    integrate(edges[i], centre, k, *kout[i], *dout[i], *tout[i]);
    kout[i]->array() *= band.cos[i].array();
    dout[i]->array() *= band.cos[i].array();
    tout[i]->array() *= band.cos[i].array();
  }
  const double norm = unit_l1 ? (kout[0]->sum() + kout[1]->sum()) / 2
                              : std::sqrt(s.width * (kout[0]->squaredNorm() + kout[1]->squaredNorm()) / 2);
  for (int i = 0; i < 2; ++i) {
    *kout[i] /= norm;
    *dout[i] /= norm * k.sigma;
    *tout[i] /= norm * k.sigma * k.sigma * k.sigma;
  }
}

}  // namespace

FloatKernelBank build_float_kernel_bank(const EstimatorSettings& s) {
  FloatKernelBank b;
  for (int i = 0; i < 2; ++i) b.edge[i] = column_edge_yaws(s.cam[i], s.width);
  b.band = build_float_column_band(s, b.edge);
  const double centre = (s.cam[0].axis_yaw + s.cam[1].axis_yaw) / 2;
  for (int i = 0; i < 2; ++i) b.axis_offset[i] = s.cam[i].axis_yaw - centre;
  Eigen::VectorXd* kn[2] = {&b.cam[0].norm, &b.cam[1].norm};
  Eigen::VectorXd* dn[2] = {&b.cam[0].norm_d, &b.cam[1].norm_d};
  Eigen::VectorXd unused[2];
  Eigen::VectorXd* tn[2] = {&unused[0], &unused[1]};
  build_kernel(s, b.edge, b.band, centre, s.normaliser, true, kn, dn, tn);
  const size_t n = s.kernels.size();
  for (auto& c : b.cam) {
    c.k.resize(n);
    c.d.resize(n);
    c.t.resize(n);
  }
  for (size_t k = 0; k < n; ++k) {
    Eigen::VectorXd* kk[2] = {&b.cam[0].k[k], &b.cam[1].k[k]};
    Eigen::VectorXd* dd[2] = {&b.cam[0].d[k], &b.cam[1].d[k]};
    Eigen::VectorXd* tt[2] = {&b.cam[0].t[k], &b.cam[1].t[k]};
    build_kernel(s, b.edge, b.band, centre, s.kernels[k], false, kk, dd, tt);
  }
  for (const KernelModel& k : s.kernels) b.sigma.push_back(k.sigma);
  // F of a uniform image: each column sums its band's rows of one value.
  for (int i = 0; i < 2; ++i) {
    FloatCameraKernels& c = b.cam[i];
    const Eigen::VectorXd& rows = b.band.rows;
    c.dc.resize(static_cast<Eigen::Index>(n));
    for (size_t k = 0; k < n; ++k) c.dc[static_cast<Eigen::Index>(k)] = c.k[k].dot(rows) / c.norm.dot(rows);
    c.dark_n = params::kNoLightMeanDn * c.norm.dot(rows);
  }
  // Each column's lean, as column_lean_q24: a central difference of the
  // elevation scale (one-sided at the ends), clamped to +-4.
  b.leaning = !b.band.banded && s.height >= 2;
  for (int i = 0; i < 2; ++i) {
    const Eigen::VectorXd sc = float_column_cos(s.cam[i], b.edge[i]);
    auto mid = [&](int u) { return (b.edge[i][u] + b.edge[i][u + 1]) / 2; };
    b.cam[i].lean = Eigen::VectorXd::Zero(s.width);
    for (int u = 0; u < s.width && b.leaning; ++u) {
      const int lo = u > 0 ? u - 1 : u, hi = u + 1 < s.width ? u + 1 : u;
      const double dpsi = mid(hi) - mid(lo);
      if (sc[u] <= 0 || sc[lo] <= 0 || sc[hi] <= 0 || dpsi == 0) continue;
      b.cam[i].lean[u] = std::clamp(-(sc[hi] - sc[lo]) / sc[u] / dpsi, -4.0, 4.0);
    }
  }
  return b;
}

}  // namespace lumavel::host
