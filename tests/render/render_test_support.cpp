#include "render_test_support.hpp"

#include "lumavel/host/render/frame_renderer.hpp"
#include "lumavel/host/render/scene.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>

namespace lumavel::host::render::test {

Scenario empty_scenario(int width, int height, double speed) {
  Scenario s;
  s.file = "test";
  s.duration_s = 1;
  s.camera.width = width;
  s.camera.height = height;
  s.background = 0;
  SegmentSpec g;
  g.duration_s = 10;
  g.v0 = g.v1 = speed;
  s.trajectory.segments.push_back(g);
  return s;
}

Scenario turning_pass(int width, int height, double duration_s) {
  Scenario s = empty_scenario(width, height);
  s.duration_s = duration_s;
  s.trajectory.segments.clear();
  SegmentSpec a;
  a.kind = SegmentKind::Arc;
  a.duration_s = duration_s / 2;
  a.v0 = 0.5;
  a.v1 = 1.5;
  a.profile = SpeedProfile::Smooth;
  a.curvature = 1.0 / 4;
  s.trajectory.segments.push_back(a);
  a.v0 = a.v1 = 1.0;
  a.curvature = -1.0 / 6;
  s.trajectory.segments.push_back(a);
  return s;
}

PlaneSpec wall_at(double y, double x0, double x1, double z0, double z1, const PatternSpec& p) {
  PlaneSpec w;
  w.name = "wall";
  // Seen from the origin looking towards +y, +x is to the right; towards -y, -x is.
  const bool left = y > 0;
  w.from[0] = left ? x0 : x1;
  w.to[0] = left ? x1 : x0;
  w.from[1] = w.to[1] = y;
  w.z_min = z0;
  w.z_max = z1;
  w.pattern = p;
  return w;
}

PatternSpec uniform(double v) {
  PatternSpec p;
  p.kind = PatternKind::Uniform;
  p.value = v;
  return p;
}

PatternSpec checker(double square, double low, double high) {
  PatternSpec p;
  p.kind = PatternKind::Checker;
  p.square_m = square;
  p.low = low;
  p.high = high;
  return p;
}

std::string temp_dir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("lumavel_render_test_" + name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir.string();
}

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::string first_line(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  return line;
}

std::vector<double> radiance(const Scenario& s, int cam) {
  const Scene scene = build_scene(s);
  const FrameRenderer fr(s, scene);
  std::vector<double> out;
  fr.render_radiance(0, cam, out);
  return out;
}

double edge_u_from_left(const std::vector<double>& img, int w, int row) {
  double sum = 0;
  for (int c = 0; c < w; ++c) sum += img[static_cast<size_t>(row * w + c)] / 255.0;
  return sum - 0.5;
}

}  // namespace lumavel::host::render::test
