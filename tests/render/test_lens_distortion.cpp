// Lens distortion in the renderer: where world points and lines land in the
// distorted image, that no distortion changes nothing, that sensor.yaml
// carries the coefficients, and that bad coefficients are refused. The
// expected positions use the radial-tangential model written out here,
// independent of the renderer's LensDistortion.
#include <CppUTest/TestHarness.h>
#include <CppUTest/MemoryLeakWarningPlugin.h>

#include <cmath>
#include <string>
#include <vector>

#include "lumavel/host/render/frame_renderer.hpp"
#include "lumavel/host/render/scenario_loader.hpp"
#include "lumavel/host/render/scene.hpp"
#include "lumavel/host/render/sensor_synthesis.hpp"
#include "render_test_support.hpp"

using namespace lumavel::host::render;
using namespace lumavel::host::render::test;

namespace {

struct Coeffs {
  double k1, k2, p1, p2;
};

// x_d = x (1 + k1 r^2 + k2 r^4) + 2 p1 x y + p2 (r^2 + 2 x^2), y_d likewise.
void model(const Coeffs& c, double x, double y, double& xd, double& yd) {
  const double r2 = x * x + y * y;
  const double radial = 1 + c.k1 * r2 + c.k2 * r2 * r2;
  xd = x * radial + 2 * c.p1 * x * y + c.p2 * (r2 + 2 * x * x);
  yd = y * radial + c.p1 * (r2 + 2 * y * y) + 2 * c.p2 * x * y;
}

Scenario lens_scenario(int w, int h, const Coeffs& c) {
  Scenario s = empty_scenario(w, h);
  s.camera.baseline_m = 0.1;  // cam0 at x = -0.05 m
  s.camera.distortion = {c.k1, c.k2, c.p1, c.p2};
  return s;
}


const Coeffs kBarrel{-0.14, 0.09, 0, 0};
const Coeffs kWithTangential{-0.14, 0.09, 0.004, -0.003};

}  // namespace

TEST_GROUP(LensDistortion){};
// yaml-cpp allocates statics on first use: not leaks of the code under test.
TEST_GROUP(LensDistortionYaml) {
  void setup() override { MemoryLeakWarningPlugin::saveAndDisableNewDeleteOverloads(); }
  void teardown() override { MemoryLeakWarningPlugin::restoreNewDeleteOverloads(); }
};


TEST(LensDistortion, KnownWorldPointLandsWhereTheModelSays) {
  // A smooth bright bump (sin x sin over a 10 cm square, 0 at its border,
  // about 8 px wide) around a known world point 2 m away, off-centre where
  // the lens moves it by over a pixel. The centroid of the rendered pixels
  // must be the model's: the bump pushed through the forward model and
  // weighted by the lens's area change, integrated here numerically.
  const int w = 160, h = 120;
  const Pinhole pin = pinhole_from_fov(w, h, 50, 40);
  const double D = 2.0, L = 0.1, x_cam = -0.05;
  const double kPi = 3.14159265358979323846;
  PatternSpec bump;
  bump.kind = PatternKind::Sinusoid;
  bump.mean = 0;
  bump.amplitude = 255;
  bump.period_h_m = bump.period_v_m = 2 * L;
  bump.product = true;
  const double pts[3][2] = {{-0.70, 0.55}, {0.62, -0.35}, {0.75, 0.6}};  // world x, z of the centre
  for (const auto& pt : pts) {
    Scenario s = lens_scenario(w, h, kWithTangential);
    s.planes.push_back(wall_at(D, pt[0] - L / 2, pt[0] + L / 2, pt[1] - L / 2, pt[1] + L / 2, bump));
    const auto img = radiance(s, 0);
    double m = 0, mu = 0, mv = 0;
    for (int r = 0; r < h; ++r)
      for (int c = 0; c < w; ++c) {
        const double v = img[static_cast<size_t>(r * w + c)];
        m += v;
        mu += v * c;
        mv += v * r;
      }
    // Expected: camera x = world x (forward), camera y = -world z, axis +y.
    constexpr int kN = 200;
    double em = 0, eu = 0, ev = 0;
    for (int j = 0; j < kN; ++j)
      for (int i = 0; i < kN; ++i) {
        const double fs = (i + 0.5) / kN, ft = (j + 0.5) / kN;
        const double weight = std::sin(kPi * fs) * std::sin(kPi * ft);
        const double x = (pt[0] - L / 2 + L * fs - x_cam) / D, y = -(pt[1] - L / 2 + L * ft) / D;
        double xd, yd, xe, ye, xn, yn;
        const double e = 1e-7;
        model(kWithTangential, x, y, xd, yd);
        model(kWithTangential, x + e, y, xe, ye);
        model(kWithTangential, x, y + e, xn, yn);
        const double jac = ((xe - xd) * (yn - yd) - (ye - yd) * (xn - xd)) / (e * e);
        em += weight * jac;
        eu += weight * jac * (pin.cu + pin.fu * xd);
        ev += weight * jac * (pin.cv + pin.fv * yd);
      }
    const double ud = eu / em, vd = ev / em;
    const double u_pin = pin.cu + pin.fu * (pt[0] - x_cam) / D, v_pin = pin.cv - pin.fv * pt[1] / D;
    CHECK(std::hypot(ud - u_pin, vd - v_pin) > 0.5);  // the lens matters here
    DOUBLES_EQUAL(ud, mu / m, 0.01);
    DOUBLES_EQUAL(vd, mv / m, 0.01);
    // Total brightness: the bump's integral over the distorted image.
    const double area_scale = (L / D * pin.fu) * (L / D * pin.fv) / (kN * kN);
    DOUBLES_EQUAL(255 * em * area_scale, m, 0.002 * m);
  }
}

TEST(LensDistortion, VerticalLineAtTheCentreStaysStraightOthersBow) {
  // A wall covering x <= x_e. Through the image centre (x_e = camera x) the
  // edge stays on column cu in every row; 0.84 m off-centre it bows the way
  // the model says: in row v_d it crosses at the model's u_d for the y that
  // distorts to v_d.
  const int w = 160, h = 120;
  const Pinhole pin = pinhole_from_fov(w, h, 50, 40);
  const double D = 2.0, x_cam = -0.05;
  {
    Scenario s = lens_scenario(w, h, kBarrel);
    s.planes.push_back(wall_at(D, -20, x_cam, -20, 20, uniform(255)));
    const auto img = radiance(s, 0);
    for (int r = 0; r < h; ++r) DOUBLES_EQUAL(pin.cu, edge_u_from_left(img, w, r), 1e-6);
  }
  Scenario s = lens_scenario(w, h, kBarrel);
  const double x_e = x_cam + 0.84;  // x = 0.42, near the image edge (0.466)
  s.planes.push_back(wall_at(D, -20, x_e, -20, 20, uniform(255)));
  const auto img = radiance(s, 0);
  const double x = (x_e - x_cam) / D;
  double lo = 1e9, hi = -1e9;
  for (int r = 0; r < h; ++r) {
    // Solve y_d(x, y) = (r - cv)/fv for y by bisection (monotonic here).
    const double target = (r - pin.cv) / pin.fv;
    double y0 = -1, y1 = 1, xd = 0, yd = 0;
    for (int i = 0; i < 100; ++i) {
      const double ym = 0.5 * (y0 + y1);
      model(kBarrel, x, ym, xd, yd);
      (yd < target ? y0 : y1) = ym;
    }
    model(kBarrel, x, 0.5 * (y0 + y1), xd, yd);
    const double ud = pin.cu + pin.fu * xd;
    DOUBLES_EQUAL(ud, edge_u_from_left(img, w, r), 0.02);
    lo = std::min(lo, edge_u_from_left(img, w, r));
    hi = std::max(hi, edge_u_from_left(img, w, r));
  }
  CHECK(hi - lo > 0.8);  // bowed by about a pixel: not a straight column
}

TEST(LensDistortionYaml, ExplicitZeroDistortionRendersTheSameBytes) {
  const std::string base =
      "duration_s: 1\n"
      "seed: 3\n"
      "camera:\n"
      "  resolution: [48, 36]\n"
      "  exposure: 0.5\n"
      "  noise_sigma: 1\n";
  const std::string rest =
      "trajectory:\n"
      "  segments:\n"
      "    - {type: straight, duration_s: 1, speed: 2}\n"
      "scene:\n"
      "  planes:\n"
      "    - {from: [-5, 2], to: [5, 2], z: [-1, 1], pattern: {type: checker, square_m: 0.13}}\n"
      "    - {from: [-1, 1.2], to: [0.3, 1.5], z: [-0.3, 0.2], pattern: {type: sinusoid}}\n";
  const Scenario plain = parse_scenario(base + rest, "plain.yaml");
  const Scenario zero = parse_scenario(base + "  distortion: [0, 0, 0, 0]\n" + rest, "zero.yaml");
  const Scene sp = build_scene(plain), sz = build_scene(zero);
  const FrameRenderer fp(plain, sp), fz(zero, sz);
  for (int i = 0; i < 3; ++i)
    for (int cam = 0; cam < 2; ++cam) {
      std::vector<uint8_t> a, b;
      fp.render(i, cam, a);
      fz.render(i, cam, b);
      CHECK(a == b);
    }
}

TEST(LensDistortion, NegligibleDistortionMatchesThePinholeAreaAverage) {
  // The distorted path (sub-pixels undistorted one by one) with a lens that
  // moves nothing by more than 1e-6 px must agree with the exact pinhole box
  // filter: checks its area averaging, occlusion and background handling.
  Scenario s = empty_scenario(64, 48);
  s.background = 40;  // (the pinhole path is exact where a plane partly covers a uniform one)
  s.planes.push_back(wall_at(2.0, -0.6, 5, -0.4, 20, uniform(90)));
  s.planes.push_back(wall_at(1.1, -0.2, 0.15, -0.1, 0.25, checker(0.03, 0, 255)));
  const auto ref = radiance(s, 0);
  s.camera.distortion = {1e-9, 0, 0, 0};
  const auto got = radiance(s, 0);
  double worst = 0;
  for (size_t k = 0; k < ref.size(); ++k) worst = std::max(worst, std::fabs(ref[k] - got[k]));
  CHECK(worst < 0.05);
}

TEST(LensDistortion, SensorYamlCarriesTheCoefficients) {
  Scenario s = lens_scenario(40, 30, kWithTangential);
  const StereoRig rig(s.camera);
  for (int cam = 0; cam < 2; ++cam) {
    const lumavel::host::CameraSensor c = camera_sensor(s, rig, cam);
    STRCMP_EQUAL("radial-tangential", c.distortion_model.c_str());
    CHECK(c.distortion == std::vector<double>({-0.14, 0.09, 0.004, -0.003}));
  }
}

TEST(LensDistortionYaml, ShippedScenarioHasTheBarrelLens) {
  const Scenario s = load_scenario(std::string(LUMAVEL_SCENARIO_DIR) + "/distorted_wall.yaml");
  CHECK_EQUAL(160, s.camera.width);
  CHECK_EQUAL(120, s.camera.height);
  DOUBLES_EQUAL(4, s.duration_s, 0);
  CHECK((s.camera.distortion == std::array<double, 4>{-0.14, 0.09, 0, 0}));
}

namespace {
std::string lens_error(const std::string& value) {
  const std::string text =
      "duration_s: 2\n"                                   // 1
      "camera:\n"                                         // 2
      "  resolution: [40, 30]\n"                          // 3
      "  distortion: " + value + "\n"                     // 4
      "trajectory:\n"                                     // 5
      "  segments:\n"                                     // 6
      "    - {type: straight, duration_s: 2, speed: 1}\n";
  try {
    parse_scenario(text, "lens.yaml");
  } catch (const ScenarioError& e) {
    return e.what();
  }
  return "(accepted)";
}
}  // namespace

TEST(LensDistortionYaml, BadCoefficientsAreRefusedWithFileAndLine) {
  const char* bad[] = {"[.nan, 0, 0, 0]", "[-0.1, .inf, 0, 0]", "0.1", "[-0.1, 0.05]",
                       "[-0.1, 0.05, 0, 0, 0]", "[a, 0, 0, 0]", "{k1: 0.1}",
                       "[-3, 0, 0, 0]"};  // the last folds the image over
  for (const char* b : bad) {
    const std::string e = lens_error(b);
    STRCMP_CONTAINS("lens.yaml:4:", e.c_str());
    STRCMP_CONTAINS("distortion", e.c_str());
  }
  STRCMP_EQUAL("(accepted)", lens_error("[-0.14, 0.09, 0.001, -0.002]").c_str());
}

// k1 = 10 at hfov 90 is one-to-one (a pincushion that only grows) but squeezes
// the view's edge to a third of its pinhole distance: a wrong coefficient, refused
// as the recording check refuses it (lens_distortion.hpp, kLensMinRadialScale).
TEST(LensDistortionYaml, AnImplausibleLensIsRefusedWithFileAndLine) {
  const std::string text =
      "duration_s: 2\n"
      "camera:\n"
      "  resolution: [40, 30]\n"
      "  fov_deg: [90, 73.74]\n"
      "  distortion: [10, 0, 0, 0]\n"
      "trajectory:\n"
      "  segments:\n"
      "    - {type: straight, duration_s: 2, speed: 1}\n";
  std::string e = "(accepted)";
  try {
    parse_scenario(text, "lens.yaml");
  } catch (const ScenarioError& err) {
    e = err.what();
  }
  STRCMP_CONTAINS("lens.yaml:5:", e.c_str());
  STRCMP_CONTAINS("times its pinhole distance from the centre", e.c_str());
}
