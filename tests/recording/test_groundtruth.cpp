// True V_xb = x of q_RS^-1 * v_RS_R, interpolated at frame times.
#include <cmath>
#include <limits>

#include "lumavel/host/groundtruth.hpp"
// CppUTest last: its leak-detector macros redefine new.
#include "CppUTest/TestHarness.h"

using namespace lumavel::host;

namespace {

// v_R = q * v_B * q^-1 (Hamilton, q = w, x, y, z).
void rotate(const double q[4], const double v[3], double out[3]) {
  const double w = q[0], x = q[1], y = q[2], z = q[3];
  const double r[3][3] = {{1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)},
                          {2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)},
                          {2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)}};
  for (int i = 0; i < 3; ++i) out[i] = r[i][0] * v[0] + r[i][1] * v[1] + r[i][2] * v[2];
}

GroundTruthSample sample(uint64_t t, const double q[4], const double v_body[3]) {
  GroundTruthSample g;
  g.t_ns = t;
  for (int i = 0; i < 4; ++i) g.q[i] = q[i];
  rotate(q, v_body, g.v);
  return g;
}

}  // namespace

TEST_GROUP(GroundTruth) {};

TEST(GroundTruth, ForwardVelocityOfARotatedBody) {
  // Yawed, pitched and rolled body moving mostly forward with some side slip.
  const double ax[3] = {0.3, -0.5, 0.8};
  const double n = std::sqrt(ax[0] * ax[0] + ax[1] * ax[1] + ax[2] * ax[2]);
  const double angle = 2.1;
  const double q[4] = {std::cos(angle / 2), std::sin(angle / 2) * ax[0] / n, std::sin(angle / 2) * ax[1] / n,
                       std::sin(angle / 2) * ax[2] / n};
  const double v_body[3] = {1.7, 0.4, -0.2};
  const GroundTruthSample g = sample(0, q, v_body);
  CHECK(std::fabs(g.v[0] - 1.7) > 0.1);  // the world-frame x is not the answer
  DOUBLES_EQUAL(1.7, body_forward_velocity(g), 1e-12);
}

TEST(GroundTruth, QuaternionIsNormalisedAndSignFree) {
  const double q[4] = {std::cos(0.4), 0, 0, std::sin(0.4)};
  const double v_body[3] = {-0.6, 0.2, 0};
  GroundTruthSample g = sample(0, q, v_body);
  for (double& c : g.q) c *= -1.003;  // -q is the same rotation; slightly off unit norm
  DOUBLES_EQUAL(-0.6, body_forward_velocity(g), 1e-12);
}

TEST(GroundTruth, InterpolatedAtFrameTimesNanOutside) {
  const double q[4] = {1, 0, 0, 0};
  const double v1[3] = {1, 0, 0}, v2[3] = {2, 5, 0}, v3[3] = {-1, 0, 0};
  const std::vector<GroundTruthSample> gt = {sample(1000, q, v1), sample(2000, q, v2), sample(4000, q, v3)};
  const std::vector<double> v = true_forward_velocity(gt, {500, 1000, 1250, 2000, 3000, 4000, 4001});
  CHECK(std::isnan(v[0]));
  DOUBLES_EQUAL(1.0, v[1], 1e-12);
  DOUBLES_EQUAL(1.25, v[2], 1e-12);
  DOUBLES_EQUAL(2.0, v[3], 1e-12);
  DOUBLES_EQUAL(0.5, v[4], 1e-12);
  DOUBLES_EQUAL(-1.0, v[5], 1e-12);
  CHECK(std::isnan(v[6]));
  CHECK(std::isnan(true_forward_velocity({}, {1000})[0]));
}

// A 1 s hole in 200 Hz ground truth (was: the straight line from 1 to 3 m/s
// across it taken as the truth of every frame inside, scored in E).
TEST(GroundTruth, NoTruthInsideAHole) {
  const double q[4] = {1, 0, 0, 0};
  const double slow[3] = {1, 0, 0}, fast[3] = {3, 0, 0};
  std::vector<GroundTruthSample> gt;
  for (uint64_t t = 0; t <= 1000000000; t += 5000000) gt.push_back(sample(t, q, slow));
  for (uint64_t t = 2000000000; t <= 3000000000; t += 5000000) gt.push_back(sample(t, q, fast));
  const std::vector<double> v = true_forward_velocity(gt, {500000000, 1002500000, 1500000000, 2500000000});
  DOUBLES_EQUAL(1.0, v[0], 1e-12);
  CHECK(std::isnan(v[1]));
  CHECK(std::isnan(v[2]));
  DOUBLES_EQUAL(3.0, v[3], 1e-12);
  // Up to 10 median intervals is interpolated (a few samples lost).
  gt.erase(gt.begin() + 100, gt.begin() + 109);  // 0.5 .. 0.545 s: a 50 ms interval
  DOUBLES_EQUAL(1.0, true_forward_velocity(gt, {520000000})[0], 1e-12);
}
