// The world: textured vertical rectangles in front of a uniform background.
#pragma once
#include <Eigen/Dense>
#include <memory>
#include <string>
#include <vector>

#include "lumavel/host/render/scenario.hpp"
#include "lumavel/host/render/surface_pattern.hpp"

namespace lumavel::host::render {

struct ScenePlane {
  std::string name;
  Eigen::Vector3d origin;  // top-left corner (at `from`, z_max)
  Eigen::Vector3d e_s;     // unit, along the base from `from` to `to`
  Eigen::Vector3d e_v;     // unit, downwards (-z)
  Eigen::Vector3d normal;  // e_s x e_v
  double length = 0, height = 0;
  std::shared_ptr<const SurfacePattern> pattern;
};

struct Scene {
  double background = 128;
  std::vector<ScenePlane> planes;
};

// Loads photographs and sets up the plane frames.
Scene build_scene(const Scenario& s);

}  // namespace lumavel::host::render
