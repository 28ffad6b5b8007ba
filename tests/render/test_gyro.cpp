// Gyro: w_z = derivative of the heading + constant bias + white noise of the
// given density, at its own rate and phase.
#include <CppUTest/TestHarness.h>

#include <cmath>

#include "lumavel/host/render/sensor_synthesis.hpp"
#include "lumavel/host/render/trajectory.hpp"
#include "render_test_support.hpp"

using namespace lumavel::host;
using namespace lumavel::host::render;

namespace {
render::Scenario turning(double bias, double density) {
  render::Scenario s = test::turning_pass(40, 30, 30);
  s.imu.rate_hz = 200;
  s.imu.offset_s = 0.0013;
  s.imu.gyro_bias_z = bias;
  s.imu.gyro_noise_density = density;
  return s;
}
}  // namespace

TEST_GROUP(Gyro){};

TEST(Gyro, YawRateIsTheHeadingDerivativePlusBias) {
  const double bias = 0.5 * 3.14159265358979323846 / 180;
  const render::Scenario s = turning(bias, 0);
  const Trajectory traj(s.trajectory);
  const auto imu = synthesize_imu(s, traj);
  CHECK(imu.size() > 5000);
  for (const auto& m : imu) {
    const double t = static_cast<double>(m.t_ns - static_cast<uint64_t>(s.start_ns)) * 1e-9;
    const double dt = 1e-5;
    const double dheading = (traj.at(t + dt).heading - traj.at(t - dt).heading) / (2 * dt);
    DOUBLES_EQUAL(dheading + bias, m.w[2], 1e-6);
    DOUBLES_EQUAL(kGravity, m.a[2], 0);
  }
}

TEST(Gyro, RunsAtItsOwnRateAndPhase) {
  const render::Scenario s = turning(0, 0);
  const auto imu = synthesize_imu(s, Trajectory(s.trajectory));
  CHECK_EQUAL(static_cast<uint64_t>(s.start_ns) + 1300000u, imu[0].t_ns);
  for (size_t k = 1; k < imu.size(); ++k) CHECK_EQUAL(5000000u, imu[k].t_ns - imu[k - 1].t_ns);
}

TEST(Gyro, WhiteNoiseHasTheGivenDensity) {
  const double density = 0.002;  // rad/s/sqrt(Hz) -> sigma = density * sqrt(200 Hz)
  const render::Scenario clean = turning(0.01, 0), noisy = turning(0.01, density);
  const auto a = synthesize_imu(clean, Trajectory(clean.trajectory));
  const auto b = synthesize_imu(noisy, Trajectory(noisy.trajectory));
  double sum = 0, sum2 = 0;
  for (size_t k = 0; k < a.size(); ++k) {
    const double e = b[k].w[2] - a[k].w[2];
    sum += e;
    sum2 += e * e;
  }
  const double n = static_cast<double>(a.size());
  const double sigma = density * std::sqrt(200.0);
  DOUBLES_EQUAL(0.0, sum / n, 5 * sigma / std::sqrt(n));  // bias stays the given one
  // Standard error of a standard deviation: sigma / sqrt(2n); allow 5 of them.
  DOUBLES_EQUAL(sigma, std::sqrt(sum2 / n), 5 * sigma / std::sqrt(2 * n));
}
