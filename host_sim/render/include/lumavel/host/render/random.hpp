// Deterministic random numbers, identical on every platform and independent
// of threading: each image / sensor gets its own stream derived from the
// scenario seed (std:: distributions are implementation-defined, so the
// Gaussian is our own Box-Muller).
#pragma once
#include <cmath>
#include <cstdint>

namespace lumavel::host::render {

inline uint64_t splitmix64(uint64_t& x) {
  uint64_t z = (x += 0x9E3779B97F4A7C15ULL);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}

// Streams: 1 = pixel noise (a = frame, b = camera), 2 = gyro, 3 = drops, 4 = accel,
// 5 = fixed patterns (a = camera, b = pattern), 6 = auto-exposure (a = camera),
// 7 = vibration (a = axis: pitch, roll, heave).
inline uint64_t stream_seed(uint64_t seed, uint64_t stream, uint64_t a = 0, uint64_t b = 0) {
  uint64_t x = seed;
  uint64_t h = splitmix64(x) ^ (stream * 0xD1B54A32D192ED03ULL);
  x = h;
  h = splitmix64(x) ^ (a * 0x8CB92BA72F3D8DD7ULL);
  x = h;
  h = splitmix64(x) ^ (b * 0xABC98388FB8FAC03ULL);
  x = h;
  return splitmix64(x);
}

class Rng {  // xoshiro256**
 public:
  explicit Rng(uint64_t seed) {
    for (auto& w : s_) w = splitmix64(seed);
  }
  uint64_t next() {
    const uint64_t r = rotl(s_[1] * 5, 7) * 9;
    const uint64_t t = s_[1] << 17;
    s_[2] ^= s_[0];
    s_[3] ^= s_[1];
    s_[1] ^= s_[2];
    s_[0] ^= s_[3];
    s_[2] ^= t;
    s_[3] = rotl(s_[3], 45);
    return r;
  }
  double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }  // [0, 1)
  double gaussian() {
    if (has_spare_) {
      has_spare_ = false;
      return spare_;
    }
    const double u1 = 1.0 - uniform();  // (0, 1]
    const double u2 = uniform();
    const double r = std::sqrt(-2.0 * std::log(u1));
    constexpr double two_pi = 6.28318530717958647692;
    spare_ = r * std::sin(two_pi * u2);
    has_spare_ = true;
    return r * std::cos(two_pi * u2);
  }

 private:
  static uint64_t rotl(uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }
  uint64_t s_[4];
  double spare_ = 0;
  bool has_spare_ = false;
};

}  // namespace lumavel::host::render
