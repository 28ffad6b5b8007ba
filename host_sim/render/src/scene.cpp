#include "lumavel/host/render/scene.hpp"

#include <cmath>

namespace lumavel::host::render {

Scene build_scene(const Scenario& s) {
  Scene scene;
  scene.background = s.background;
  PatternFactory patterns;
  for (const auto& p : s.planes) {
    ScenePlane q;
    q.name = p.name;
    const Eigen::Vector3d a(p.from[0], p.from[1], p.z_max);
    const Eigen::Vector3d b(p.to[0], p.to[1], p.z_max);
    q.origin = a;
    q.length = (b - a).norm();
    q.height = p.z_max - p.z_min;
    q.e_s = (b - a) / q.length;
    q.e_v = Eigen::Vector3d(0, 0, -1);
    q.normal = q.e_s.cross(q.e_v);
    q.pattern = patterns.make(p.pattern);
    scene.planes.push_back(std::move(q));
  }
  return scene;
}

}  // namespace lumavel::host::render
