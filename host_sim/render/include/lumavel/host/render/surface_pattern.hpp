// Gray level painted on a plane, in plane coordinates (s along the plane, v
// downwards from its top edge, metres). Patterns give exact integrals over
// axis-aligned rectangles so a pixel is the true area average of the scene
// (box filter), cheap at any resolution.
#pragma once
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "lumavel/host/render/scenario.hpp"

namespace lumavel::host::render {

class SurfacePattern {
 public:
  virtual ~SurfacePattern() = default;
  // Integral of the gray level over [s0, s1] x [v0, v1] (s0 <= s1, v0 <= v1).
  virtual double integral(double s0, double s1, double v0, double v1) const = 0;
  double mean_over(double s0, double s1, double v0, double v1) const;
};

// Summed-area table of a gray photograph's tile unit (the photo, or the photo
// and its mirrored copies, 2w x 2h): texels are constant squares, so a
// bilinear lookup of the table is the exact integral. Shared by all planes
// that use the same file and tiling.
struct PhotoTable {
  PhotoTable(const std::vector<unsigned char>& px, int w, int h, Tiling tiling);
  double unit_F(double x, double y) const;  // 0 <= x <= uw, 0 <= y <= uh, texel units
  int uw = 0, uh = 0;
  std::vector<double> sat;  // (uw+1) x (uh+1)
  double mean = 0;
  Tiling tiling = Tiling::None;
};

// A photo of physical size size_m placed at offset_m on the plane; beyond
// it: mirror or repeat tiling, or (none) a plain surface at the photo's mean.
class PhotoPattern : public SurfacePattern {
 public:
  PhotoPattern(std::shared_ptr<const PhotoTable> table, const PatternSpec& spec);
  double integral(double s0, double s1, double v0, double v1) const override;
  double mean() const { return t_->mean; }

 private:
  double F(double x, double y) const;  // antiderivative in texel units
  std::shared_ptr<const PhotoTable> t_;
  double sx_ = 1, sy_ = 1;             // texels per metre
  double ox_ = 0, oy_ = 0;             // photo origin on the plane, m
  double inv_uw_ = 1, inv_uh_ = 1, inv_texel_area_ = 1;
};

// Builds patterns, loading each photograph file (per tiling) once.
class PatternFactory {
 public:
  std::unique_ptr<SurfacePattern> make(const PatternSpec& spec);

 private:
  std::vector<std::pair<std::string, std::shared_ptr<const PhotoTable>>> photos_;
};

std::unique_ptr<SurfacePattern> make_pattern(const PatternSpec& spec);

// 8-bit gray pixels of a PNG (any colour type, converted), JPEG or binary PGM.
// Throws std::runtime_error naming the file.
std::vector<unsigned char> load_photo_gray(const std::string& path, int& w, int& h);

}  // namespace lumavel::host::render
