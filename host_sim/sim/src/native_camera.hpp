// hal::StereoCamera over a recording at the sensors' own resolution, frames
// as decoded, not binned: the vo engine's input above the 160 columns that
// lumavel::bin_area (and FileStereoCamera) handle. Decodes on the calling
// thread; the VO costs far more per frame than the PNG decoding.
#pragma once
#include <string>

#include "lumavel/hal/camera.hpp"
#include "lumavel/host/recording.hpp"

namespace lumavel::host {

class NativeStereoCamera : public hal::StereoCamera {
 public:
  // `rec` must outlive the camera. Throws RecordingError when the two
  // sensors do not share one resolution.
  explicit NativeStereoCamera(const Recording& rec);
  uint16_t width() const override { return width_; }
  uint16_t height() const override { return height_; }
  // kError for a bad frame (wrong size, corrupt): error() names file and frame.
  hal::CaptureStatus capture(hal::StereoImage& out) override;
  const std::string& error() const { return error_; }

 private:
  const Recording& rec_;
  uint16_t width_, height_;
  size_t next_ = 0;
  std::string error_;
};

}  // namespace lumavel::host
