#include "lumavel/host/render/photometric_response.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "lumavel/host/render/random.hpp"

namespace lumavel::host::render {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Sub-streams of the fixed-pattern stream, one per pattern, so that adding
// one pattern does not change the others.
enum Pattern : uint64_t { kPixelGain = 0, kPixelOffset = 1, kColumnGain = 2, kColumnOffset = 3 };

std::vector<double> draw(uint64_t seed, int cam, Pattern what, size_t n, double sigma) {
  std::vector<double> v(n, 0.0);
  if (sigma <= 0) return v;
  Rng rng(stream_seed(seed, 5, static_cast<uint64_t>(cam), what));
  for (double& x : v) x = sigma * rng.gaussian();
  return v;
}

}  // namespace

CameraResponse::CameraResponse(const PhotometricSpec& spec, uint64_t seed, int cam, int width, int height,
                               double t_begin, double t_end)
    : spec_(spec), ideal_(spec.ideal()) {
  if (ideal_) return;
  const size_t w = static_cast<size_t>(width), n = w * static_cast<size_t>(height);
  const auto prnu = draw(seed, cam, kPixelGain, n, spec.prnu);
  const auto dsnu = draw(seed, cam, kPixelOffset, n, spec.dsnu);
  const auto col_gain = draw(seed, cam, kColumnGain, w, spec.column_gain);
  const auto col_offset = draw(seed, cam, kColumnOffset, w, spec.column_offset);
  pixel_gain_.resize(n);
  pixel_offset_.resize(n);
  const double cu = 0.5 * (width - 1), cv = 0.5 * (height - 1);
  const double r2_corner = 0.25 * (static_cast<double>(width) * width + static_cast<double>(height) * height);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const size_t k = static_cast<size_t>(y) * w + static_cast<size_t>(x);
      const double r = std::sqrt(((x - cu) * (x - cu) + (y - cv) * (y - cv)) / r2_corner);
      pixel_gain_[k] = vignetting(r) * (1 + prnu[k]) * (1 + col_gain[static_cast<size_t>(x)]);
      pixel_offset_[k] = spec.black_level + dsnu[k] + col_offset[static_cast<size_t>(x)];
    }
  }
  const AutoExposureSpec& ae = spec.auto_exposure;
  if (ae.sigma > 0) {
    knot_t0_ = t_begin - ae.interval_s;
    const size_t knots = static_cast<size_t>(std::ceil((t_end - knot_t0_) / ae.interval_s)) + 2;
    Rng rng(stream_seed(seed, 6, static_cast<uint64_t>(cam)));
    knots_.resize(knots);
    for (double& g : knots_) g = rng.gaussian();
  }
}

double CameraResponse::vignetting(double r) const {
  const double r2 = r * r;
  return 1 + spec_.vignetting[0] * r2 + spec_.vignetting[1] * r2 * r2;
}

double CameraResponse::exposure_gain(double t) const {
  if (knots_.empty()) return spec_.gain;
  const double x = std::max(0.0, (t - knot_t0_) / spec_.auto_exposure.interval_s);
  const size_t last = knots_.size() - 1;
  const size_t k = std::min(static_cast<size_t>(x), last);
  const double f = k == last ? 0.0 : x - static_cast<double>(k);
  const double a = knots_[k], b = knots_[std::min(k + 1, last)];
  const double g = a + (b - a) * 0.5 * (1 - std::cos(kPi * f));  // smooth: no kink at the values
  return spec_.gain * std::exp(spec_.auto_exposure.sigma * g);
}

void CameraResponse::apply(double t, std::vector<double>& image) const {
  if (ideal_) return;
  if (image.size() != pixel_gain_.size())
    throw std::invalid_argument("CameraResponse::apply: image size differs from the camera's");
  const double gain = exposure_gain(t);
  const bool curve = spec_.gamma != 1.0;
  for (size_t k = 0; k < image.size(); ++k) {
    double s = gain * pixel_gain_[k] * image[k];
    if (curve) s = 255 * std::pow(std::max(s, 0.0) / 255, spec_.gamma);
    image[k] = s + pixel_offset_[k];
  }
}

}  // namespace lumavel::host::render
