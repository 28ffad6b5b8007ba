// The world-like scenes are at the distances host_sim/scenarios/README.md
// claims: depths (along the optical axis) of what the cameras see, sampled
// over the whole run with the renderer's own ray casting.
#include <CppUTest/TestHarness.h>
// after TestHarness.h, which it needs
#include <CppUTest/MemoryLeakWarningPlugin.h>

#include <algorithm>
#include <string>
#include <vector>

#include "lumavel/host/render/frame_renderer.hpp"
#include "lumavel/host/render/scenario_loader.hpp"
#include "lumavel/host/render/scene.hpp"
#include "lumavel/host/render/view_renderer.hpp"

using namespace lumavel::host::render;

namespace {

struct DepthCensus {
  double nearest = 1e300, farthest = 0;
  std::vector<double> near_share;  // per sampled frame: share of the image closer than `near_m`
  double far_share = 0;            // over all samples: share in [far_lo, far_hi]
};

// Both cameras, every `step_s`, a 32 x 24 grid of pixel centres.
DepthCensus census(const std::string& file, double step_s, double near_m, double far_lo, double far_hi) {
  const Scenario s = load_scenario(std::string(LUMAVEL_SCENARIO_DIR) + "/" + file);
  const Scene scene = build_scene(s);
  const FrameRenderer fr(s, scene);
  const Pinhole& pin = fr.rig().pinhole();
  DepthCensus c;
  double far = 0, all = 0;
  for (double t = 0; t < s.duration_s; t += step_s) {
    for (int cam = 0; cam < 2; ++cam) {
      const RigidPose T = fr.rig().camera_in_world(cam, fr.trajectory().at(t));
      int near = 0, n = 0;
      for (int j = 0; j < 24; ++j) {
        for (int i = 0; i < 32; ++i) {
          Eigen::Vector3d p;
          ++n;
          if (!pixel_hit(scene, pin, T, (i + 0.5) * pin.width / 32 - 0.5, (j + 0.5) * pin.height / 24 - 0.5, p))
            continue;  // background (floor, sky)
          const double depth = (T.R.transpose() * (p - T.t)).z();
          c.nearest = std::min(c.nearest, depth);
          c.farthest = std::max(c.farthest, depth);
          near += depth < near_m;
          far += depth >= far_lo && depth <= far_hi;
          all += 1;
        }
      }
      c.near_share.push_back(static_cast<double>(near) / n);
    }
  }
  c.far_share = far / all;
  return c;
}

// Share of the sampled frames in which at least `share` of the image is near.
double frames_with_near(const DepthCensus& c, double share) {
  double k = 0;
  for (double v : c.near_share) k += v >= share;
  return k / static_cast<double>(c.near_share.size());
}

}  // namespace

// load_scenario's yaml-cpp statics would be reported by CppUTest's leak check;
// the AddressSanitizer build checks leaks instead.
TEST_GROUP(SceneDepths) {
  void setup() override { MemoryLeakWarningPlugin::saveAndDisableNewDeleteOverloads(); }
  void teardown() override { MemoryLeakWarningPlugin::restoreNewDeleteOverloads(); }
};

// Clutter 0.3 to 1 m away fills at least a fifth of the view almost all the
// time; a third of what is seen is the far room at 3 to 6 m.
TEST(SceneDepths, NearClutterIsAt0_3To1mBeforeAFarRoom) {
  const DepthCensus c = census("near_clutter.yaml", 0.1, 1.0, 3.0, 6.2);
  DOUBLES_EQUAL(0.30, c.nearest, 0.02);
  CHECK(c.farthest <= 6.2);
  CHECK(frames_with_near(c, 0.2) >= 0.9);
  CHECK(c.far_share >= 0.25);
}

// Parked cars (1.7 m and beyond) fill a fifth of the view in three frames
// out of four; facades at 5 to 15 m are a third of what is seen.
TEST(SceneDepths, StreetPassCarsAt1_7mFacadesTo15m) {
  const DepthCensus c = census("street_pass.yaml", 0.1, 2.6, 5.0, 15.5);
  DOUBLES_EQUAL(1.68, c.nearest, 0.03);  // a wheel, 2 cm before the nearest car's side
  CHECK(c.farthest <= 15.5);
  CHECK(frames_with_near(c, 0.2) >= 0.7);
  CHECK(c.far_share >= 0.3);
}

// Clutter from 0.3 m (the cable) to 3 m (the back wall).
TEST(SceneDepths, BackAndForthClutterFrom0_3To3m) {
  const DepthCensus c = census("back_and_forth.yaml", 0.1, 1.0, 1.6, 3.1);
  DOUBLES_EQUAL(0.30, c.nearest, 0.02);
  CHECK(c.farthest <= 3.1);
  CHECK(frames_with_near(c, 0.2) >= 0.35);
  CHECK(c.far_share >= 0.3);
}
