#include "lumavel/host/lens_remap.hpp"

#include <cmath>
#include <stdexcept>

namespace lumavel::host {

LensRemap::LensRemap(int width, int height, const PinholeIntrinsics& k, const LensDistortion& lens)
    : width_(width), height_(height) {
  if (width < 1 || height < 1) throw std::invalid_argument("LensRemap: empty image");
  taps_.resize(static_cast<size_t>(width) * static_cast<size_t>(height));
  for (int v = 0; v < height; ++v)
    for (int u = 0; u < width; ++u) {
      double xd = 0, yd = 0;
      lens.distort((u - k.cu) / k.fu, (v - k.cv) / k.fv, xd, yd);
      double su = k.fu * xd + k.cu, sv = k.fv * yd + k.cv;
      if (!(su >= 0 && su <= width - 1 && sv >= 0 && sv <= height - 1)) {
        ++outside_;
        su = std::isfinite(su) ? std::fmin(std::fmax(su, 0.0), width - 1.0) : k.cu;
        sv = std::isfinite(sv) ? std::fmin(std::fmax(sv, 0.0), height - 1.0) : k.cv;
      }
      // Fractions rounded to 1/256; a fraction that rounds to 256 moves to the next pixel.
      int iu = static_cast<int>(std::floor(su)), iv = static_cast<int>(std::floor(sv));
      int fu = static_cast<int>(std::lround((su - iu) * 256)), fv = static_cast<int>(std::lround((sv - iv) * 256));
      if (fu == 256) ++iu, fu = 0;
      if (fv == 256) ++iv, fv = 0;
      if (iu > width - 1) iu = width - 1, fu = 0;
      if (iv > height - 1) iv = height - 1, fv = 0;
      Tap& t = taps_[static_cast<size_t>(v) * static_cast<size_t>(width) + static_cast<size_t>(u)];
      t.index = static_cast<uint32_t>(iv) * static_cast<uint32_t>(width) + static_cast<uint32_t>(iu);
      t.fx = static_cast<uint8_t>(fu);
      t.fy = static_cast<uint8_t>(fv);
      t.dx = iu < width - 1 ? 1 : 0;
      t.dy = iv < height - 1 ? 1 : 0;
    }
}

void LensRemap::apply(const uint8_t* src, uint8_t* dst) const {
  const size_t n = taps_.size();
  const uint32_t w = static_cast<uint32_t>(width_);
  for (size_t i = 0; i < n; ++i) {
    const Tap& t = taps_[i];
    const uint8_t* p = src + t.index;
    const uint32_t a = p[0], b = p[t.dx], c = p[t.dy * w], d = p[t.dy * w + t.dx];
    const uint32_t top = a * (256u - t.fx) + b * t.fx, bottom = c * (256u - t.fx) + d * t.fx;
    dst[i] = static_cast<uint8_t>((top * (256u - t.fy) + bottom * t.fy + 32768u) >> 16);
  }
}

}  // namespace lumavel::host
