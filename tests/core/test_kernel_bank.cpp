// Kernel tables: hand-checkable properties and agreement with the double twin.
#include <CppUTest/TestHarness.h>

#include <cmath>
#include <cstdio>
#include <memory>

#include "lumavel/core/estimator.hpp"
#include "lumavel/host/float_kernel_bank.hpp"
#include "synthetic_rig.hpp"

using namespace lumavel;

namespace {
double value(const KernelTable& t, int u) { return std::ldexp(t.w[u], -(31 + t.exp)); }

struct Banks {
  host::EstimatorSettings s;
  std::unique_ptr<KernelBank> fixed = std::make_unique<KernelBank>();
  host::FloatKernelBank dbl;
  explicit Banks(const host::EstimatorSettings& set) : s(set) {
    build_kernel_bank(host::to_fixed_config(s), *fixed);
    dbl = host::build_float_kernel_bank(s);
  }
};
}  // namespace

TEST_GROUP(KernelBank){};

TEST(KernelBank, GaussianDerivativeValues) {
  // phi_0(0) = 1, phi_1(1) = -e^-0.5, phi_2(0) = -1, phi_3(1) = -(1 - 3) e^-0.5 = 2 e^-0.5
  DOUBLES_EQUAL(1.0, std::ldexp(gaussian_derivative_q30(0, 0), -30), 1e-8);
  DOUBLES_EQUAL(-std::exp(-0.5), std::ldexp(gaussian_derivative_q30(1, 1 << 24), -30), 1e-8);
  DOUBLES_EQUAL(-1.0, std::ldexp(gaussian_derivative_q30(2, 0), -30), 1e-8);
  DOUBLES_EQUAL(2 * std::exp(-0.5), std::ldexp(gaussian_derivative_q30(3, 1 << 24), -30), 1e-8);
}

TEST(KernelBank, PinholeEdgesOfASymmetricCamera) {
  test::SyntheticRig rig;
  const EstimatorConfig c = host::to_fixed_config(rig.settings());
  AngleQ28 e[kMaxColumns + 1];
  pinhole_column_edges(c.cam[0], c.width, e);
  // Outer edges at axis -+ hfov/2 (u_sign = -1: yaw decreases to the right).
  DOUBLES_EQUAL(rig.axis(0) + rig.hfov / 2, std::ldexp(e[0], -28), 1e-6);  // fu, cu are Q16
  DOUBLES_EQUAL(rig.axis(0) - rig.hfov / 2, std::ldexp(e[c.width], -28), 1e-6);
  DOUBLES_EQUAL(rig.axis(0), std::ldexp(e[c.width / 2], -28), 1e-6);
}

TEST(KernelBank, NormalisationAndSymmetry) {
  test::SyntheticRig rig;
  Banks b(rig.settings());
  const int w = rig.width;
  for (int i = 0; i < 2; ++i) {
    double l1 = 0;
    for (int u = 0; u < w; ++u) l1 += value(b.fixed->cam[i].norm, u);
    DOUBLES_EQUAL(1.0, l1, 1e-6);  // aligned rig: each camera's window sums to 1
    for (int k = 0; k < b.fixed->count; ++k) {
      double l2 = 0;
      for (int u = 0; u < w; ++u) l2 += value(b.fixed->cam[i].k[k], u) * value(b.fixed->cam[i].k[k], u);
      DOUBLES_EQUAL(1.0 / w, l2, 1e-8);
      // Order 1 is odd and order 2 even about the view's centre.
      const int sign = rig.settings().kernels[static_cast<size_t>(k)].order % 2 ? -1 : 1;
      for (int u = 0; u < w; ++u)
        DOUBLES_EQUAL(sign * value(b.fixed->cam[i].k[k], w - 1 - u), value(b.fixed->cam[i].k[k], u), 1e-8);
    }
  }
}

TEST(KernelBank, FixedTablesMatchTheDoubleTwin) {
  // The twin is given the quantised inputs (fu, cu in Q16, angles in Q28), so
  // that the gap measures the integer arithmetic alone.
  test::SyntheticRig rig;
  rig.misalignment = 1.6 * M_PI / 180;
  for (int w : {20, 40, 160}) {
    rig.width = w;
    host::EstimatorSettings s = rig.settings();
    const EstimatorConfig c = host::to_fixed_config(s);
    for (int i = 0; i < 2; ++i) {
      s.cam[i].fu = std::ldexp(c.cam[i].fu, -16);
      s.cam[i].cu = std::ldexp(c.cam[i].cu, -16);
      s.cam[i].axis_yaw = std::ldexp(c.cam[i].axis_yaw, -28);
    }
    for (size_t k = 0; k < s.kernels.size(); ++k) s.kernels[k].sigma = std::ldexp(c.kernels[k].sigma, -28);
    s.normaliser.sigma = std::ldexp(c.normaliser.sigma, -28);
    Banks b(s);
    double worst = 0;
    for (int i = 0; i < 2; ++i)
      for (int k = 0; k < b.fixed->count; ++k) {
        const auto& dk = b.dbl.cam[i].k[static_cast<size_t>(k)];
        const auto& dd = b.dbl.cam[i].d[static_cast<size_t>(k)];
        const double peak_k = dk.cwiseAbs().maxCoeff(), peak_d = dd.cwiseAbs().maxCoeff();
        for (int u = 0; u < w; ++u) {
          worst = std::fmax(worst, std::fabs(value(b.fixed->cam[i].k[k], u) - dk[u]) / peak_k);
          worst = std::fmax(worst, std::fabs(value(b.fixed->cam[i].d[k], u) - dd[u]) / peak_d);
        }
      }
    std::printf("\n  %d px: worst fixed-vs-double table gap %.2e of the peak", w, worst);
    CHECK(worst < 1e-6);
  }
}


// Both engines sum the same pixels with the same weights: the core's band
// (whole rows and 1/256 boundary weights) is the twin's row weights, column
// by column, on narrow, wide, short and misaligned rigs.
TEST(KernelBank, BandRowsMatchTheDoubleTwin) {
  int banded = 0, columns = 0, differ = 0;
  for (double hfov_deg : {30.0, 50.0, 90.0, 120.0})
    for (int w : {20, 40, 160})
      for (int h : {4, 15, 30, 120})
        for (double mis_deg : {0.0, 1.6, -3.0}) {
          test::SyntheticRig rig;
          rig.width = w;
          rig.height = h;
          rig.hfov = hfov_deg * M_PI / 180;
          rig.misalignment = mis_deg * M_PI / 180;
          host::EstimatorSettings s = rig.settings();
          s.kernels = host::default_kernels(rig.hfov);
          s.elevation_band = true;
          const EstimatorConfig c = host::to_fixed_config(s);
          auto bank = std::make_unique<KernelBank>();
          build_kernel_bank(c, *bank);
          const host::FloatKernelBank dbl = host::build_float_kernel_bank(s);
          CHECK_EQUAL(dbl.band.banded, bank->banded);
          banded += bank->banded;
          for (int u = 0; u < w; ++u) {
            ++columns;
            const double rows = std::ldexp(band_rows_q8(bank->column_band(), static_cast<uint16_t>(h), static_cast<uint16_t>(u)), -8);
            differ += rows != dbl.band.rows[u];
          }
        }
  std::printf("\n  %d of 144 rigs banded; %d of %d columns' rows differ", banded, differ, columns);
  LONGS_EQUAL(0, differ);
}
