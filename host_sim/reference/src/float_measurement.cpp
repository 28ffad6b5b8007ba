// Twin of firmware/core/src/measurement.cpp.
#include "lumavel/host/float_measurement.hpp"

#include <algorithm>
#include <cmath>

#include "lumavel/core/estimator_params.hpp"

namespace lumavel::host {
namespace {

struct CameraOutputs {
  Eigen::VectorXd f, r, c;  // F, dF/dtheta, d3F/dtheta3 per kernel
  bool no_light = false;
};

// F_k = B_k / N (paper eq. 21 applied after the kernel); dF/dtheta = (dB - F dN) / N.
// With the bank leaning, dB/dtheta and dN/dtheta gain the edge-row correction
// sum_u K[u] lean[u] E[u] (the core's measurement.hpp says why), and F its
// first-order move to the centre axis by the camera's axis offset.
CameraOutputs camera_outputs(const FloatColumnProfile& p, const FloatCameraKernels& k, Eigen::Index n, bool leaning,
                             double offset) {
  CameraOutputs out;
  const Eigen::VectorXd& col = p.sum;
  const double nrm = k.norm.dot(col);
  out.f = Eigen::VectorXd::Zero(n);
  out.r = Eigen::VectorXd::Zero(n);
  out.c = Eigen::VectorXd::Zero(n);
  if (nrm <= 0 || nrm < k.dark_n) {  // (the core's kNoLightMeanDn)
    out.no_light = true;
    return out;
  }
  const bool lean = leaning && p.edge.size() == col.size();
  const Eigen::VectorXd corr = lean ? Eigen::VectorXd(k.lean.cwiseProduct(p.edge)) : Eigen::VectorXd();
  const auto correction = [&](const Eigen::VectorXd& t) { return lean ? t.dot(corr) / nrm : 0.0; };
  const double dn = k.norm_d.dot(col) / nrm + correction(k.norm);
  for (Eigen::Index j = 0; j < n; ++j) {
    const size_t jj = static_cast<size_t>(j);
    out.f[j] = k.k[jj].dot(col) / nrm;
    // (the core's: F taken back to the centre axis, F - offset (C_k - F C_N) / N)
    if (lean && offset != 0) out.f[j] -= offset * (correction(k.k[jj]) - out.f[j] * correction(k.norm));
    out.r[j] = k.d[jj].dot(col) / nrm + correction(k.k[jj]) - out.f[j] * dn;
    out.c[j] = k.t[jj].dot(col) / nrm;  // derivatives of N neglected: a correction term
  }
  return out;
}

// Kernel k's output as a local sinusoid: omega^2 = -C R / R^2 and
// z_i = (F_i - dc) - i R_i / omega; arg(z1 conj(z0)) = k h, halved.
double half_phase(const CameraOutputs& c0, const CameraOutputs& c1, double dc0, double dc1, double sigma,
                  Eigen::Index k) {
  const double rr = c0.r[k] * c0.r[k] + c1.r[k] * c1.r[k];
  if (rr <= 0) return 0;
  const double w2 = -(c0.c[k] * c0.r[k] + c1.c[k] * c1.r[k]) / rr;
  const double u = std::clamp(w2 * sigma * sigma, params::kSigmaW2Min, params::kSigmaW2Max);  // (sigma w)^2
  const double omega = std::sqrt(u) / sigma;
  const double a0 = c0.f[k] - dc0, b0 = -c0.r[k] / omega;
  const double a1 = c1.f[k] - dc1, b1 = -c1.r[k] / omega;
  return std::atan2(b1 * a0 - a1 * b0, a1 * a0 + b1 * b0) / 2;
}

}  // namespace

FloatStereoMeasurement float_stereo_measurement(const FloatColumnProfile& p0, const FloatColumnProfile& p1,
                                                const FloatKernelBank& bank,
                                                const FloatPhotometricBalance* balance) {
  FloatStereoMeasurement m;
  const auto n = static_cast<Eigen::Index>(bank.sigma.size());
  CameraOutputs c[2] = {camera_outputs(p0, bank.cam[0], n, bank.leaning, bank.axis_offset[0]),
                        camera_outputs(p1, bank.cam[1], n, bank.leaning, bank.axis_offset[1])};
  m.no_light = c[0].no_light || c[1].no_light;
  m.balance = Eigen::VectorXd::Zero(n);
  if (balance && !m.no_light)
    for (Eigen::Index j = 0; j < n; ++j) {
      m.balance[j] = balance->offset(j);
      c[1].f[j] -= m.balance[j];
    }
  m.mid = (c[0].f + c[1].f) / 2;
  m.diff = c[1].f - c[0].f;
  m.rot = (c[0].r + c[1].r) / 2;
  for (int i = 0; i < 2; ++i) {
    m.f[i] = c[i].f;
    m.r[i] = c[i].r;
  }
  m.clipped = p0.clipped + p1.clipped;
  m.half_phase = Eigen::VectorXd::Zero(n);
  for (Eigen::Index j = 0; j < n && !m.no_light; ++j)
    m.half_phase[j] =
        half_phase(c[0], c[1], bank.cam[0].dc[j], bank.cam[1].dc[j], bank.sigma[static_cast<size_t>(j)], j);
  return m;
}

}  // namespace lumavel::host
