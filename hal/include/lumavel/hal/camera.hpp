// Stereo camera: delivers both frames of one trigger at the working resolution.
// The driver bins larger sensor frames (lumavel::bin_area) before handing them on.
#pragma once
#include <cstdint>

namespace lumavel::hal {

enum class CaptureStatus : uint8_t { kOk, kEnd, kError };

struct StereoImage {
  uint64_t t_ns;       // middle of the exposure
  uint8_t* cam[2];     // caller-owned buffers, width * height bytes each
  uint16_t width;
  uint16_t height;
};

class StereoCamera {
 public:
  virtual ~StereoCamera() = default;
  virtual uint16_t width() const = 0;   // working resolution
  virtual uint16_t height() const = 0;
  // Blocks until the next pair is in `out`; kEnd when a recording is exhausted.
  virtual CaptureStatus capture(StereoImage& out) = 0;
};

}  // namespace lumavel::hal
