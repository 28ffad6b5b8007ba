#include "lumavel/host/render/surface_pattern.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace lumavel::host::render {
namespace {
constexpr double kPi = 3.14159265358979323846;

class UniformPattern : public SurfacePattern {
 public:
  explicit UniformPattern(double v) : v_(v) {}
  double integral(double s0, double s1, double v0, double v1) const override {
    return v_ * (s1 - s0) * (v1 - v0);
  }

 private:
  double v_;
};

// mean + amplitude * (sum: (sin a + sin b) / 2, product: sin a sin b)
class SinusoidPattern : public SurfacePattern {
 public:
  explicit SinusoidPattern(const PatternSpec& p)
      : mean_(p.mean),
        amp_(p.amplitude),
        ws_(2 * kPi / p.period_h_m),
        wv_(2 * kPi / p.period_v_m),
        ps_(p.phase_h_deg * kPi / 180),
        pv_(p.phase_v_deg * kPi / 180),
        product_(p.product) {}
  double integral(double s0, double s1, double v0, double v1) const override {
    // Integrals of sin(w x + p) over the two intervals, analytically.
    const double is = (std::cos(ws_ * s0 + ps_) - std::cos(ws_ * s1 + ps_)) / ws_;
    const double iv = (std::cos(wv_ * v0 + pv_) - std::cos(wv_ * v1 + pv_)) / wv_;
    const double ls = s1 - s0, lv = v1 - v0;
    const double var = product_ ? is * iv : 0.5 * (is * lv + iv * ls);
    return mean_ * ls * lv + amp_ * var;
  }

 private:
  double mean_, amp_, ws_, wv_, ps_, pv_;
  bool product_;
};

// Squares of side q; the square at the plane's top-left corner is `high`.
class CheckerPattern : public SurfacePattern {
 public:
  explicit CheckerPattern(const PatternSpec& p)
      : q_(p.square_m), mid_(0.5 * (p.high + p.low)), half_(0.5 * (p.high - p.low)) {}
  double integral(double s0, double s1, double v0, double v1) const override {
    return mid_ * (s1 - s0) * (v1 - v0) + half_ * (G(s1) - G(s0)) * (G(v1) - G(v0));
  }

 private:
  // Antiderivative of the +-1 square wave (period 2q): a triangle wave.
  double G(double x) const {
    const double r = x - 2 * q_ * std::floor(x / (2 * q_));
    return r < q_ ? r : 2 * q_ - r;
  }
  double q_, mid_, half_;
};

// The photo's pixels; its errors name the scenario's line as the loader's
// do (the photo is decoded when the scene is built, after the loader).
std::vector<unsigned char> load_photo(const PatternSpec& spec, int& w, int& h) {
  try {
    return load_photo_gray(spec.file, w, h);
  } catch (const std::runtime_error& e) {
    if (spec.file_at.empty()) throw;
    throw std::runtime_error(spec.file_at + ": photo " + e.what());
  }
}

}  // namespace

double SurfacePattern::mean_over(double s0, double s1, double v0, double v1) const {
  const double a = (s1 - s0) * (v1 - v0);
  if (a > 0) return integral(s0, s1, v0, v1) / a;
  constexpr double e = 1e-4;  // degenerate box: the value around the point
  return integral(s0 - e, s0 + e, v0 - e, v0 + e) / (4 * e * e);
}

PhotoTable::PhotoTable(const std::vector<unsigned char>& px, int w, int h, Tiling t) : tiling(t) {
  const bool mirror = tiling == Tiling::Mirror;
  uw = mirror ? 2 * w : w;
  uh = mirror ? 2 * h : h;
  const size_t stride = static_cast<size_t>(uw) + 1;
  sat.assign(stride * (static_cast<size_t>(uh) + 1), 0.0);
  double total = 0;
  for (int y = 0; y < uh; ++y) {
    const int sy = y < h ? y : 2 * h - 1 - y;
    double row = 0;
    for (int x = 0; x < uw; ++x) {
      const int sxx = x < w ? x : 2 * w - 1 - x;
      row += px[static_cast<size_t>(sy) * static_cast<size_t>(w) + static_cast<size_t>(sxx)];
      sat[(static_cast<size_t>(y) + 1) * stride + static_cast<size_t>(x) + 1] =
          sat[static_cast<size_t>(y) * stride + static_cast<size_t>(x) + 1] + row;
    }
    total += row;
  }
  mean = total / (static_cast<double>(uw) * uh);
}

// Bilinear lookup of the table = exact integral of constant texels.
double PhotoTable::unit_F(double x, double y) const {
  const int i = std::min(static_cast<int>(x), uw - 1);
  const int j = std::min(static_cast<int>(y), uh - 1);
  const double a = x - i, b = y - j;
  const size_t stride = static_cast<size_t>(uw) + 1;
  const double* r0 = &sat[static_cast<size_t>(j) * stride + static_cast<size_t>(i)];
  const double* r1 = r0 + stride;
  return r0[0] + a * (r0[1] - r0[0]) + b * (r1[0] - r0[0]) + a * b * (r1[1] - r1[0] - r0[1] + r0[0]);
}

PhotoPattern::PhotoPattern(std::shared_ptr<const PhotoTable> table, const PatternSpec& spec)
    : t_(std::move(table)), ox_(spec.offset_h_m), oy_(spec.offset_v_m) {
  const int w = t_->tiling == Tiling::Mirror ? t_->uw / 2 : t_->uw;
  const int h = t_->tiling == Tiling::Mirror ? t_->uh / 2 : t_->uh;
  sx_ = w / spec.width_m;
  sy_ = h / spec.height_m;
  inv_uw_ = 1.0 / t_->uw;
  inv_uh_ = 1.0 / t_->uh;
  inv_texel_area_ = 1.0 / (sx_ * sy_);
}

double PhotoPattern::F(double x, double y) const {
  const PhotoTable& T = *t_;
  if (T.tiling == Tiling::None) {
    // Outside the photo the surface is plain at the photo's mean.
    const double cx = std::clamp(x, 0.0, static_cast<double>(T.uw));
    const double cy = std::clamp(y, 0.0, static_cast<double>(T.uh));
    return T.mean * (x * y - cx * cy) + T.unit_F(cx, cy);
  }
  // Periodic: x = k P + r, y = l Q + q.
  const double P = T.uw, Q = T.uh;
  const double k = std::floor(x * inv_uw_), l = std::floor(y * inv_uh_);
  const double r = std::clamp(x - k * P, 0.0, P), q = std::clamp(y - l * Q, 0.0, Q);
  return k * l * T.unit_F(P, Q) + k * T.unit_F(P, q) + l * T.unit_F(r, Q) + T.unit_F(r, q);
}

double PhotoPattern::integral(double s0, double s1, double v0, double v1) const {
  const PhotoTable& T = *t_;
  const double x0 = (s0 - ox_) * sx_, x1 = (s1 - ox_) * sx_;
  const double y0 = (v0 - oy_) * sy_, y1 = (v1 - oy_) * sy_;
  if (T.tiling != Tiling::None) {
    // Fast path: the box lies inside one tile unit (nearly always).
    const double bx = std::floor(x0 * inv_uw_) * T.uw, by = std::floor(y0 * inv_uh_) * T.uh;
    if (x1 - bx <= T.uw && y1 - by <= T.uh) {
      const double a0 = std::max(x0 - bx, 0.0), a1 = x1 - bx;
      const double b0 = std::max(y0 - by, 0.0), b1 = y1 - by;
      return (T.unit_F(a1, b1) - T.unit_F(a0, b1) - T.unit_F(a1, b0) + T.unit_F(a0, b0)) *
             inv_texel_area_;
    }
  }
  return (F(x1, y1) - F(x0, y1) - F(x1, y0) + F(x0, y0)) * inv_texel_area_;  // texel -> m^2
}

std::unique_ptr<SurfacePattern> PatternFactory::make(const PatternSpec& spec) {
  if (spec.kind != PatternKind::Photo) return make_pattern(spec);
  const std::string key = spec.file + (spec.tiling == Tiling::Mirror ? "#mirror" : "#plain");
  for (const auto& p : photos_)
    if (p.first == key) return std::make_unique<PhotoPattern>(p.second, spec);
  int w = 0, h = 0;
  const auto px = load_photo(spec, w, h);
  auto table = std::make_shared<const PhotoTable>(px, w, h, spec.tiling);
  photos_.emplace_back(key, table);
  return std::make_unique<PhotoPattern>(table, spec);
}

std::unique_ptr<SurfacePattern> make_pattern(const PatternSpec& spec) {
  switch (spec.kind) {
    case PatternKind::Uniform:
      return std::make_unique<UniformPattern>(spec.value);
    case PatternKind::Sinusoid:
      return std::make_unique<SinusoidPattern>(spec);
    case PatternKind::Checker:
      return std::make_unique<CheckerPattern>(spec);
    case PatternKind::Photo: {
      int w = 0, h = 0;
      const auto px = load_photo(spec, w, h);
      return std::make_unique<PhotoPattern>(std::make_shared<const PhotoTable>(px, w, h, spec.tiling), spec);
    }
  }
  throw std::logic_error("unknown pattern kind");
}

}  // namespace lumavel::host::render
