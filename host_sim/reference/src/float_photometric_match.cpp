// Twin of firmware/core/src/photometric_match.cpp.
#include "lumavel/host/float_photometric_match.hpp"

#include <algorithm>
#include <cmath>

#include "lumavel/core/photometric_params.hpp"

namespace lumavel::host {
namespace {

using namespace params;

constexpr int kMemorySamples = 1 << kMatchMemoryLog2;
constexpr double kForget = 1.0 / kMemorySamples;
const double kInvPrior2[FloatPhotometricMatch::kParams] = {
    kMatchSampleCorrelation / (kMatchPriorTilt * kMatchPriorTilt),
    kMatchSampleCorrelation / (kMatchPriorVignetting * kMatchPriorVignetting),
    kMatchSampleCorrelation * kMatchOffsetUnitDn * kMatchOffsetUnitDn / (kMatchPriorOffsetDn * kMatchPriorOffsetDn)};
const double kMaxParam[FloatPhotometricMatch::kParams] = {kMatchMaxShape, kMatchMaxShape,
                                                          kMatchMaxOffsetDn / kMatchOffsetUnitDn};
constexpr double kHeld = 4.0;  // |J|, |z| held as the core holds them

double column_x(int u, int width) { return static_cast<double>(2 * u + 1 - width) / width; }
double gain(const FloatPhotometricMatch::Params& p, double x) { return 1 + p[0] * x + p[1] * x * x; }
double hold(double v) { return std::clamp(v, -kHeld, kHeld); }

}  // namespace

FloatColumnProfile FloatPhotometricMatch::apply(const FloatColumnProfile& p1, const Eigen::VectorXd& rows) const {
  FloatColumnProfile out = p1;
  const int w = static_cast<int>(p1.sum.size());
  for (int u = 0; u < w; ++u) {
    const double g = gain(p_, column_x(u, w));
    const double radial = p1.radial ? p_[1] * (p1.sum_y2[u] - p1.rows_y2 * p_[2] * kMatchOffsetUnitDn) : 0.0;
    out.sum[u] = std::max(0.0, (p1.sum[u] - rows[u] * p_[2] * kMatchOffsetUnitDn) * g + radial);
    if (out.edge.size()) out.edge[u] = p1.edge[u] * g;
  }
  return out;
}

Eigen::MatrixXd FloatPhotometricMatch::jacobian(const FloatColumnProfile& p1, const Eigen::VectorXd& rows,
                                                const FloatCameraKernels& ck, const Eigen::VectorXd& f1) const {
  const int count = static_cast<int>(f1.size()), w = static_cast<int>(p1.sum.size());
  Eigen::MatrixXd jac = Eigen::MatrixXd::Zero(count, kParams);
  const double n = ck.norm.dot(p1.sum);
  if (n <= 0) return jac;
  Eigen::VectorXd du(w);
  for (int j = 0; j < kParams; ++j) {
    for (int u = 0; u < w; ++u) {
      const double x = column_x(u, w);
      const double y2 = p1.radial ? p1.sum_y2[u] : 0.0, rows_y2 = p1.radial ? p1.rows_y2 : 0.0;
      du[u] = j == 0   ? p1.sum[u] * x
              : j == 1 ? p1.sum[u] * x * x + y2
                       : -(rows[u] * gain(p_, x) + rows_y2 * p_[1]) * kMatchOffsetUnitDn;
    }
    const double dn = ck.norm.dot(du) / n;
    for (int k = 0; k < count; ++k) jac(k, j) = ck.k[static_cast<size_t>(k)].dot(du) / n - f1[k] * dn;
  }
  return jac;
}

bool FloatPhotometricMatch::learn(const Input& in) {
  p_before_ = p_;
  if (!in.usable) {
    hist_.clear();
    return false;
  }
  hist_.push_back({in.t_ns, in.heading, {*in.f[0], *in.f[1] - *in.jac * p_}, {*in.r[0], *in.r[1]}, *in.jac});
  if (hist_.size() > static_cast<size_t>(kMatchFrames)) hist_.pop_front();
  if (std::fabs(in.v) < kMatchMinSpeed || in.baseline == 0 || hist_.size() < 2) return false;
  const double tau_ns = std::fabs(in.baseline / in.v) * 1e9;
  const int lead = (in.v > 0) == (in.baseline > 0) ? 1 : 0;
  const size_t newest = hist_.size() - 1;
  const double now = static_cast<double>(in.t_ns);
  if (now >= tau_ns) sample(newest, 1 - lead, now - tau_ns, lead, in.max_rotation);
  for (size_t i = newest; i-- > 0;) {
    const double tt = static_cast<double>(hist_[i].t_ns) + tau_ns;
    if (tt <= now) {
      sample(i, lead, tt, lead, in.max_rotation);
      break;
    }
  }
  if (samples_ < kMatchFirstSamples || unsolved_ < kMatchSolveSamples) return false;
  unsolved_ = 0;
  return solve();
}

void FloatPhotometricMatch::sample(size_t fixed, int fixed_cam, double t_other, int lead, double max_rotation) {
  const Frame& fx = hist_[fixed];
  for (size_t i = 1; i < hist_.size(); ++i) {
    const Frame &a = hist_[i - 1], &b = hist_[i];
    if (t_other < static_cast<double>(a.t_ns) || t_other > static_cast<double>(b.t_ns)) continue;
    const double u = (t_other - static_cast<double>(a.t_ns)) / static_cast<double>(b.t_ns - a.t_ns);
    const int other = 1 - fixed_cam;
    const bool fixed_leads = fixed_cam == lead;
    const double ho = a.heading + (b.heading - a.heading) * u;
    const double dth = fixed_leads ? ho - fx.heading : fx.heading - ho;
    if (std::fabs(dth) > max_rotation) return;
    const Eigen::VectorXd fo = a.f[other] + (b.f[other] - a.f[other]) * u;
    const Eigen::VectorXd ro = a.r[other] + (b.r[other] - a.r[other]) * u;
    const Eigen::VectorXd& rl = fixed_leads ? fx.r[lead] : ro;
    const Eigen::VectorXd fl = (fixed_leads ? fx.f[lead] : fo) + dth * rl;
    const Eigen::VectorXd ft = fixed_leads ? fo : fx.f[1 - lead];
    const Eigen::VectorXd& f1 = lead == 1 ? fl : ft;
    const Eigen::VectorXd& f0 = lead == 1 ? ft : fl;
    Eigen::VectorXd z = (f0 - f1).unaryExpr(&hold);
    Eigen::MatrixXd jj = (fixed_cam == 1 ? fx.jac : Eigen::MatrixXd(a.jac + (b.jac - a.jac) * u)).unaryExpr(&hold);
    const Eigen::VectorXd d = (b.f[other] - a.f[other]).unaryExpr(&hold);
    double rows = static_cast<double>(z.size());
    if (d.squaredNorm() > 16.0 / 1099511627776.0) {  // the core's 16 in Q40
      const Eigen::VectorXd dh = d / d.norm();
      z -= dh * dh.dot(z);
      jj -= dh * (dh.transpose() * jj);
      rows -= 1;
    }
    if (samples_ >= kMemorySamples) {
      a_ *= 1 - kForget;
      b_ *= 1 - kForget;
      ee_ *= 1 - kForget;
      zz_ *= 1 - kForget;
      dof_ *= 1 - kForget;
      ee_rows_ *= 1 - kForget;
    } else {
      ++samples_;
    }
    ++unsolved_;
    if (solved_) {
      ee_ += (z - jj * est_).squaredNorm();
      ee_rows_ += rows;
    }
    zz_ += z.squaredNorm();
    a_ += jj.transpose() * jj;
    b_ += jj.transpose() * z;
    dof_ += rows;
    return;
  }
}

bool FloatPhotometricMatch::solve() {
  // (the core's photometric_match.cpp: about the last solution, or all of it before one)
  const double rows = solved_ ? ee_rows_ : dof_;
  const double free_rows = rows > kParams + 1 ? rows - kParams : 1;
  const double s2 = (solved_ ? ee_ : zz_) / free_rows;
  Eigen::Matrix<double, kParams, kParams> m = a_;
  for (int i = 0; i < kParams; ++i) m(i, i) += s2 * kInvPrior2[i];
  const Params p = m.ldlt().solve(b_);
  for (int i = 0; i < kParams; ++i)
    if (!std::isfinite(p[i]) || std::fabs(p[i]) > kMaxParam[i]) return false;
  est_ = p;
  solved_ = true;
  const double explained = p.dot(b_);
  if (zz_ > 0 && explained > 0)
    weight_ = std::max(weight_, std::clamp((explained / zz_ - kMatchExplainedNone) /
                                               (kMatchExplainedAll - kMatchExplainedNone), 0.0, 1.0));
  const Params applied = weight_ * p;
  const bool changed = applied != p_;
  p_ = applied;
  return changed;
}

}  // namespace lumavel::host
