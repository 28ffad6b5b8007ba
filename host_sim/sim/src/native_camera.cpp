#include "native_camera.hpp"

#include <cstring>

#include "lumavel/host/image_io.hpp"
#include "lumavel/host/path_check.hpp"
#include "lumavel/host/recording_layout.hpp"

namespace lumavel::host {

NativeStereoCamera::NativeStereoCamera(const Recording& rec)
    : rec_(rec), width_(static_cast<uint16_t>(rec.cam[0].width)), height_(static_cast<uint16_t>(rec.cam[0].height)) {
  if (rec.cam[1].width != rec.cam[0].width || rec.cam[1].height != rec.cam[0].height)
    throw recording_error_in(rec.root + "/" + layout::kCamDir[1] + "/sensor.yaml",
                             "resolution differs from cam0's: unbinned frames need one size");
}

hal::CaptureStatus NativeStereoCamera::capture(hal::StereoImage& out) {
  if (!error_.empty()) return hal::CaptureStatus::kError;
  if (next_ >= rec_.frames.size()) return hal::CaptureStatus::kEnd;
  const FramePairEntry& f = rec_.frames[next_];
  for (int c = 0; c < 2; ++c) {
    const std::string frame = "frame " + std::to_string(next_) + " (t=" + std::to_string(f.t_ns) + " ns, " +
                              layout::kCamDir[c] + "): ";
    try {
      const GrayImage img = read_gray_image(f.path[c], width_, height_);  // of another size: not decoded
      if (img.width != width_ || img.height != height_) {
        error_ = frame + shown_path(f.path[c]) + ": image is " + std::to_string(img.width) + "x" + std::to_string(img.height) +
                 ", sensor.yaml says resolution [" + std::to_string(width_) + ", " + std::to_string(height_) + "]";
        return hal::CaptureStatus::kError;
      }
      std::memcpy(out.cam[c], img.px.data(), img.px.size());
    } catch (const RecordingError& e) {
      error_ = frame + e.what();
      return hal::CaptureStatus::kError;
    }
  }
  out.t_ns = f.t_ns;
  out.width = width_;
  out.height = height_;
  ++next_;
  return hal::CaptureStatus::kOk;
}

}  // namespace lumavel::host
