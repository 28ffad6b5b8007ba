// The photometric match's model and Jacobian (firmware/core/photometric_match.hpp):
// the mapping of a column profile, and dF1/dp against finite differences of
// the camera's outputs through the measurement.
#include <CppUTest/TestHarness.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>
#include <algorithm>

#include "lumavel/core/estimator.hpp"
#include "synthetic_rig.hpp"

using namespace lumavel;

namespace {

int32_t q30(double v) { return static_cast<int32_t>(std::llround(v * 1073741824.0)); }

struct Scene {
  test::SyntheticRig rig;
  std::unique_ptr<KernelBank> bank = std::make_unique<KernelBank>();
  ColumnProfile p0{}, p1{};
  RadialSums radial1{};
  Scene() {
    rig.width = 40;
    rig.height = 30;
    build_kernel_bank(host::to_fixed_config(rig.settings()), *bank);
    const test::Pose2 at{0.3, 0, 0};
    const auto a = rig.render(0, at), b = rig.render(1, at);
    column_profile(a.data(), 40, 30, 40, bank->column_band(), p0);
    CHECK_TRUE(column_profile(b.data(), 40, 30, 40, bank->column_band(), p1, bank->radial_rings(), &radial1));
  }
  // cam1's outputs with the mapping p applied
  StereoMeasurement measure(const double p[3], MatchJac* jac = nullptr, bool radial = false) const {
    PhotometricMatch m;
    const int32_t pq[3] = {q30(p[0]), q30(p[1]), q30(p[2] / 64)};
    m.set_params(pq);
    ColumnProfile q = p1;
    const RadialSums* r = radial ? &radial1 : nullptr;
    m.apply(q, bank->column_band(), 30, r);
    StereoMeasurement out{};
    stereo_measurement(p0, q, *bank, nullptr, out);
    if (jac) m.jacobian(q, bank->column_band(), 30, r, bank->cam[1], bank->count, out.f[1], *jac);
    return out;
  }
};

}  // namespace

TEST_GROUP(PhotometricMatch){};

// sum' = (sum - rows beta) (1 + a1 x + a2 x^2), x the column's centre in (-1, 1),
// plus a2 (sum_y2 - rows_y2 beta) with cam1's radial sums.
TEST(PhotometricMatch, MapsTheColumnSums) {
  Scene sc;
  PhotometricMatch m;
  const int32_t p[3] = {q30(0.02), q30(-0.05), q30(3.0 / 64)};
  m.set_params(p);
  for (const bool radial : {false, true}) {
    ColumnProfile q = sc.p1;
    m.apply(q, sc.bank->column_band(), 30, radial ? &sc.radial1 : nullptr);
    for (int u = 0; u < 40; ++u) {
      const double x = (2.0 * u + 1 - 40) / 40;
      double want = (sc.p1.sum[u] - 30 * 3.0) * (1 + 0.02 * x - 0.05 * x * x);
      if (radial) want += -0.05 * (sc.radial1.sum_y2[u] - sc.radial1.rows_y2_q8 * 3.0) / 256;
      CHECK(q.q8);  // the mapped sums keep 8 fractional bits
      CHECK(std::fabs(q.sum[u] / 256.0 - want) <= 1.0 / 256);
    }
  }
}

// dF1/dp from jacobian() against central differences of F1 through the
// measurement: the Jacobian takes d sum'/d a_j as sum' x^j (not divided by
// the gain), which at p = 0 is exact and at a 5 % vignetting is 5 % off.
TEST(PhotometricMatch, JacobianIsTheDerivativeOfTheOutputs) {
  Scene sc;
  for (const bool radial : {false, true})
  for (const double vig : {0.0, -0.05}) {
    const double p[3] = {0.0, vig, 0.0};
    MatchJac jac{};
    sc.measure(p, &jac, radial);
    const double step[3] = {2e-3, 2e-3, 0.5};
    double worst = 0;  // per parameter, against that column's largest derivative
    for (int j = 0; j < 3; ++j) {
      double lo[3] = {p[0], p[1], p[2]}, hi[3] = {p[0], p[1], p[2]};
      lo[j] -= step[j];
      hi[j] += step[j];
      const StereoMeasurement a = sc.measure(lo, nullptr, radial), b = sc.measure(hi, nullptr, radial);
      const double unit = j == 2 ? 64 : 1;  // beta's Jacobian is per 64 DN
      double fd[kMaxKernels], largest = 0;
      for (int k = 0; k < sc.bank->count; ++k) {
        fd[k] = (b.f[1][k] - a.f[1][k]) / (2 * step[j]) * unit / 268435456.0;
        largest = std::max(largest, std::fabs(fd[k]));
      }
      for (int k = 0; k < sc.bank->count; ++k)
        worst = std::max(worst, std::fabs(jac[k][j] / 268435456.0 - fd[k]) / largest);
    }
    std::printf("\n  a2 %.2f%s: worst |J - finite difference| %.2f %% of it", vig, radial ? " (radial)" : "", 100 * worst);
    CHECK(worst < (vig == 0 ? 0.01 : 0.08));
  }
}

// A radial vignetting difference, cam1 = cam0 / (1 + v (x^2 + y^2)) + beta
// per pixel (the model's own form): the profile mapped with the rows' share (radial column sums) has the
// shape of cam0's to a small fraction of what the columns alone leave (the
// rows' share of a column sum follows the scene's vertical layout).
TEST(PhotometricMatch, MapsTheRowsShareOfARadialVignetting) {
  Scene sc;
  const test::Pose2 at{0.3, 0, 0};
  const auto a = sc.rig.render(0, at);
  const double v = 0.2, beta = 4.0;
  std::vector<uint8_t> b(a.size());
  for (int y = 0; y < 30; ++y)
    for (int x = 0; x < 40; ++x) {
      const double xc = (2.0 * x + 1 - 40) / 40, yc = (2.0 * y + 1 - 30) / 40;
      const double px = a[static_cast<size_t>(y * 40 + x)] / (1 + v * (xc * xc + yc * yc)) + beta;
      b[static_cast<size_t>(y * 40 + x)] = static_cast<uint8_t>(std::lround(std::min(255.0, px)));
    }
  ColumnProfile p0{}, plain{}, radial{};
  RadialSums sums{};
  column_profile(a.data(), 40, 30, 40, sc.bank->column_band(), p0);
  column_profile(b.data(), 40, 30, 40, sc.bank->column_band(), plain);
  CHECK_TRUE(column_profile(b.data(), 40, 30, 40, sc.bank->column_band(), radial, sc.bank->radial_rings(), &sums));
  // cam1 -> cam0: (b - beta)(1 + v r^2)
  PhotometricMatch m;
  const int32_t p[3] = {0, q30(v), q30(beta / 64)};
  m.set_params(p);
  double err[2];
  int i = 0;
  for (ColumnProfile* q : {&plain, &radial}) {
    m.apply(*q, sc.bank->column_band(), 30, q == &radial ? &sums : nullptr);
    double s0 = 0, s1 = 0;
    for (int u = 0; u < 40; ++u) {
      s0 += p0.sum[u];
      s1 += q->sum[u] / 256.0;
    }
    double e = 0;  // the shapes, the gain divided out (as the estimator's N does)
    for (int u = 0; u < 40; ++u) e += std::pow(q->sum[u] / 256.0 / s1 - p0.sum[u] / s0, 2);
    err[i++] = std::sqrt(e / 40) * 40;
  }
  std::printf("\n  rms shape error: columns alone %.2e, with the rows' share %.2e", err[0], err[1]);
  CHECK(err[1] < err[0] / 3);
}
