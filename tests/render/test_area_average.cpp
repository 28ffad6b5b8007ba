// Area averaging: a pixel is the exact mean of the scene over its area
// (texture edges, plane edges against the background, occlusion, photo
// texels through the summed-area table, analytic sinusoid).
#include <CppUTest/TestHarness.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "lumavel/host/render/frame_renderer.hpp"
#include "lumavel/host/render/scene.hpp"
#include "lumavel/host/render/surface_pattern.hpp"
#include "render_test_support.hpp"

using namespace lumavel::host::render;
using namespace lumavel::host::render::test;

namespace {

// World x on the wall at distance d that projects to image column u.
double x_at_u(const Pinhole& p, double u, double d) { return (u - p.cu) * d / p.fu; }

Scenario single_camera_scene() {
  Scenario s = empty_scenario(40, 30);
  s.camera.baseline_m = 0;  // cam0 at the body origin
  return s;
}

// Exact integral of a tiled texel grid over a rectangle (texel units), by
// brute force over the texels it overlaps.
double brute_integral(const std::vector<unsigned char>& px, int w, int h, Tiling tiling, double x0,
                      double x1, double y0, double y1) {
  auto texel = [&](long i, long j) -> double {
    auto wrap = [&](long k, int n) -> long {
      if (tiling == Tiling::Repeat) return ((k % n) + n) % n;
      const long p = ((k % (2 * n)) + 2 * n) % (2 * n);  // mirror
      return p < n ? p : 2 * n - 1 - p;
    };
    return px[static_cast<size_t>(wrap(j, h) * w + wrap(i, w))];
  };
  double sum = 0;
  for (long j = static_cast<long>(std::floor(y0)); j < static_cast<long>(std::ceil(y1)); ++j) {
    const double jd = static_cast<double>(j);
    const double oy = std::min(y1, jd + 1) - std::max(y0, jd);
    for (long i = static_cast<long>(std::floor(x0)); i < static_cast<long>(std::ceil(x1)); ++i) {
      const double id = static_cast<double>(i);
      const double ox = std::min(x1, id + 1) - std::max(x0, id);
      sum += ox * oy * texel(i, j);
    }
  }
  return sum;
}

}  // namespace

TEST_GROUP(AreaAverage){};

TEST(AreaAverage, HalfBlackHalfWhiteEdgeGivesTheExactFraction) {
  // Checker of 10 m squares: white (255) for s < 10 m, black beyond. Put the
  // boundary at u = 20.3: pixel 20 ([19.5, 20.5]) is 0.8 white.
  Scenario s = single_camera_scene();
  const Pinhole p = pinhole_from_fov(40, 30, 50, 40);
  const double xe = x_at_u(p, 20.3, 2.0);
  s.planes.push_back(wall_at(2.0, xe - 10, xe + 10, -20, 5, checker(10, 0, 255)));
  const auto img = radiance(s);
  for (int row : {0, 14, 29}) {
    DOUBLES_EQUAL(255.0, img[static_cast<size_t>(row * 40 + 19)], 1e-9);
    DOUBLES_EQUAL(0.8 * 255.0, img[static_cast<size_t>(row * 40 + 20)], 1e-9);
    DOUBLES_EQUAL(0.0, img[static_cast<size_t>(row * 40 + 21)], 1e-9);
  }
}

TEST(AreaAverage, HorizontalEdgeToo) {
  // Checker boundary at t = 10 m from the top, placed at v = 7.75: pixel row 7
  // ([6.5, 7.5]) is white, row 8 ([7.5, 8.5]) is 0.25 white.
  Scenario s = single_camera_scene();
  const Pinhole p = pinhole_from_fov(40, 30, 50, 40);
  const double ze = -(7.75 - p.cv) * 2.0 / p.fv;  // image down = world down
  s.planes.push_back(wall_at(2.0, -3, 7, -20, ze + 10, checker(10, 0, 255)));
  // s < 10 m everywhere in view (x from -3), so parity follows t only.
  const auto img = radiance(s);
  DOUBLES_EQUAL(255.0, img[7 * 40 + 5], 1e-9);
  DOUBLES_EQUAL(0.25 * 255.0, img[8 * 40 + 5], 1e-9);
  DOUBLES_EQUAL(0.0, img[9 * 40 + 5], 1e-9);
}

TEST(AreaAverage, PlaneEdgeMixesWithTheBackground) {
  Scenario s = single_camera_scene();
  s.background = 40;
  const Pinhole p = pinhole_from_fov(40, 30, 50, 40);
  s.planes.push_back(wall_at(2.0, -20, x_at_u(p, 10.25, 2.0), -20, 20, uniform(200)));
  const auto img = radiance(s);
  DOUBLES_EQUAL(200.0, img[5 * 40 + 9], 1e-9);
  DOUBLES_EQUAL(0.75 * 200 + 0.25 * 40, img[5 * 40 + 10], 1e-9);
  DOUBLES_EQUAL(40.0, img[5 * 40 + 11], 1e-9);
}

TEST(AreaAverage, NearPlaneOccludesFarPlane) {
  Scenario s = single_camera_scene();
  const Pinhole p = pinhole_from_fov(40, 30, 50, 40);
  s.planes.push_back(wall_at(3.0, -20, 20, -20, 20, uniform(200)));                    // far
  s.planes.push_back(wall_at(1.0, -20, x_at_u(p, 30.4, 1.0), -20, 20, uniform(100)));  // near
  const auto img = radiance(s);
  DOUBLES_EQUAL(100.0, img[3 * 40 + 29], 1e-9);
  DOUBLES_EQUAL(0.9 * 100 + 0.1 * 200, img[3 * 40 + 30], 1e-9);
  DOUBLES_EQUAL(200.0, img[3 * 40 + 31], 1e-9);
}

TEST(AreaAverage, AbuttingPlanesLeaveNoGap) {
  // Two sections of one wall meeting at u = 20.3: the seam pixel is 0.8 of
  // one and 0.2 of the other, none of the background.
  Scenario s = single_camera_scene();
  s.background = 0;
  const Pinhole p = pinhole_from_fov(40, 30, 50, 40);
  const double xe = x_at_u(p, 20.3, 2.0);
  s.planes.push_back(wall_at(2.0, -20, xe, -20, 20, uniform(100)));
  s.planes.push_back(wall_at(2.0, xe, 20, -20, 20, uniform(200)));
  const Scene scene = build_scene(s);
  const FrameRenderer fr(s, scene);
  std::vector<double> img;
  const FrameStats st = fr.render_radiance(0, 0, img);
  DOUBLES_EQUAL(0.8 * 100 + 0.2 * 200, img[12 * 40 + 20], 1e-9);
  DOUBLES_EQUAL(0.0, st.background_fraction, 1e-12);
}

TEST(AreaAverage, PhotoWallPixelsAreTexelBlockMeans) {
  // An 8x6 texel photo exactly filling a 4x3 image: each pixel covers a 2x2
  // block of texels and must be its mean.
  const int tw = 8, th = 6;
  std::vector<unsigned char> px(tw * th);
  for (int k = 0; k < tw * th; ++k) px[static_cast<size_t>(k)] = static_cast<unsigned char>((k * 37 + 11) % 256);
  const std::string dir = temp_dir("photo_block");
  const std::string file = dir + "/photo.pgm";
  {
    FILE* f = std::fopen(file.c_str(), "wb");
    std::fprintf(f, "P5\n%d %d\n255\n", tw, th);
    std::fwrite(px.data(), 1, px.size(), f);
    std::fclose(f);
  }
  Scenario s = empty_scenario(4, 3);
  s.camera.baseline_m = 0;
  const double d = 1.5;
  const double half_w = d * std::tan(25 * 3.14159265358979323846 / 180);
  const double half_h = d * std::tan(20 * 3.14159265358979323846 / 180);
  PatternSpec photo;
  photo.kind = PatternKind::Photo;
  photo.file = file;
  photo.width_m = 2 * half_w;
  photo.height_m = 2 * half_h;
  s.planes.push_back(wall_at(d, -half_w, half_w, -half_h, half_h, photo));
  const auto img = radiance(s);
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 4; ++c) {
      double mean = 0;
      for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 2; ++i) mean += px[static_cast<size_t>((2 * r + j) * tw + 2 * c + i)] / 4.0;
      DOUBLES_EQUAL(mean, img[static_cast<size_t>(r * 4 + c)], 1e-6);
    }
  }
}

TEST(AreaAverage, SummedAreaTableIsExactForAnyRectangleAndTiling) {
  const int w = 7, h = 5;
  std::vector<unsigned char> px(w * h);
  for (int k = 0; k < w * h; ++k) px[static_cast<size_t>(k)] = static_cast<unsigned char>((k * 53 + 7) % 251);
  PatternSpec spec;
  spec.kind = PatternKind::Photo;
  spec.width_m = w;  // 1 texel per metre: plane units = texel units
  spec.height_m = h;
  const double rects[][4] = {{0.3, 2.7, 0.1, 4.9},   {-3.2, 9.6, -1.5, 7.25}, {6.9, 7.1, 4.95, 5.05},
                             {13.5, 30.2, 9.1, 22.7}, {-20.4, -6.1, -11, -2}, {2, 2.5, 3, 3.25}};
  for (Tiling tiling : {Tiling::Mirror, Tiling::Repeat}) {
    spec.tiling = tiling;
    PhotoPattern pat(std::make_shared<const PhotoTable>(px, w, h, tiling), spec);
    for (const auto& r : rects)
      DOUBLES_EQUAL(brute_integral(px, w, h, tiling, r[0], r[1], r[2], r[3]), pat.integral(r[0], r[1], r[2], r[3]),
                    1e-7 * (1 + std::fabs(brute_integral(px, w, h, tiling, r[0], r[1], r[2], r[3]))));
  }
  // No tiling: the photo, then a plain surface at its mean.
  spec.tiling = Tiling::None;
  PhotoPattern plain(std::make_shared<const PhotoTable>(px, w, h, Tiling::None), spec);
  DOUBLES_EQUAL(brute_integral(px, w, h, Tiling::Repeat, 1.5, 3.5, 0.5, 2.5), plain.integral(1.5, 3.5, 0.5, 2.5), 1e-9);
  DOUBLES_EQUAL(plain.mean() * 6.0, plain.integral(10, 13, 20, 22), 1e-9);
}

TEST(AreaAverage, SinusoidIntegralMatchesNumericalIntegration) {
  PatternSpec spec;
  spec.kind = PatternKind::Sinusoid;
  spec.mean = 127.5;
  spec.amplitude = 127.5;
  spec.period_h_m = 0.5;
  spec.period_v_m = 0.6;
  spec.phase_h_deg = 30;
  for (bool product : {false, true}) {
    spec.product = product;
    const auto pat = make_pattern(spec);
    const double s0 = 0.13, s1 = 0.71, v0 = -0.2, v1 = 0.45;
    const int n = 800;
    double num = 0;
    for (int j = 0; j < n; ++j) {
      for (int i = 0; i < n; ++i) {
        const double s = s0 + (i + 0.5) * (s1 - s0) / n, v = v0 + (j + 0.5) * (v1 - v0) / n;
        const double a = std::sin(2 * 3.14159265358979323846 * s / 0.5 + 3.14159265358979323846 / 6);
        const double b = std::sin(2 * 3.14159265358979323846 * v / 0.6);
        num += 127.5 + 127.5 * (product ? a * b : 0.5 * (a + b));
      }
    }
    num *= (s1 - s0) * (v1 - v0) / (static_cast<double>(n) * n);
    DOUBLES_EQUAL(num, pat->integral(s0, s1, v0, v1), 1e-4);
  }
}
