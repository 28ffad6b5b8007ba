#include "lumavel/host/file_camera.hpp"

#include <cstring>

#include "lumavel/core/binning.hpp"
#include "lumavel/core/clip_match.hpp"
#include "lumavel/host/image_io.hpp"
#include "lumavel/host/path_check.hpp"
#include "lumavel/host/recording_layout.hpp"
#include "lumavel/host/rig.hpp"

namespace lumavel::host {

FileStereoCamera::FileStereoCamera(const Recording& rec, int width, int height, int threads, int lookahead,
                                   FrameProcessing processing)
    : rec_(rec),
      width_(static_cast<uint16_t>(width)),
      height_(static_cast<uint16_t>(height)),
      match_clipping_(processing.match_clipping) {
  // Beyond the sensor: run's rule and words, naming the resolution's line
  // (was: 'sensor.yaml: cannot bin 20x15 frames to 40x30', a second wording
  // of it, which lumavel_recording_to_stream showed).
  check_bins_down(rec, {width, height});
  for (int c = 0; c < 2; ++c)
    if (width < 1 || height < 1 || width > 2048)
      throw recording_error_in(rec.root + "/" + layout::kCamDir[c] + "/sensor.yaml",
                               "cannot bin " + std::to_string(rec.cam[c].width) + "x" +
                                   std::to_string(rec.cam[c].height) + " frames to " + std::to_string(width) + "x" +
                                   std::to_string(height));
  for (int c = 0; c < 2; ++c) {
    const CameraSensor& s = rec.cam[c];
    if (processing.undistort && lens_applies(s))
      remap_[c] = std::make_unique<LensRemap>(s.width, s.height, PinholeIntrinsics{s.fu, s.fv, s.cu, s.cv}, lens_of(s));
  }
  if (threads < 1) threads = 1;
  if (lookahead < threads) lookahead = threads;
  slots_.resize(static_cast<size_t>(lookahead));
  for (Slot& s : slots_)
    for (auto& p : s.px) p.resize(static_cast<size_t>(width) * static_cast<size_t>(height));
  try {
    for (int i = 0; i < threads; ++i) threads_.emplace_back([this] { worker(); });
  } catch (...) {  // could not start a thread: stop the ones running, then report
    {
      std::lock_guard<std::mutex> lock(mu_);
      stop_ = true;
    }
    slot_free_.notify_all();
    for (std::thread& t : threads_) t.join();
    throw;
  }
}

FileStereoCamera::~FileStereoCamera() {
  {
    std::lock_guard<std::mutex> lock(mu_);
    stop_ = true;
  }
  slot_free_.notify_all();
  for (std::thread& t : threads_) t.join();
}

void FileStereoCamera::decode_into(size_t index, Slot& slot) const {
  const FramePairEntry& f = rec_.frames[index];
  const auto frame_of = [&](int c) {
    return "frame " + std::to_string(index) + " (t=" + std::to_string(f.t_ns) + " ns, " + layout::kCamDir[c] + "): ";
  };
  GrayImage img[2];
  ImageView view[2];
  for (int c = 0; c < 2; ++c) {
    const std::string frame = frame_of(c);
    const CameraSensor& s = rec_.cam[c];
    try {
      img[c] = read_gray_image(f.path[c], s.width, s.height);  // of another size: not decoded
    } catch (const RecordingError& e) {
      throw RecordingError(frame + e.what());
    }
    if (img[c].width != s.width || img[c].height != s.height)
      throw RecordingError(frame + shown_path(f.path[c]) + ": image is " + std::to_string(img[c].width) + "x" +
                           std::to_string(img[c].height) + ", sensor.yaml says resolution [" +
                           std::to_string(s.width) + ", " + std::to_string(s.height) + "]");
    view[c] = ImageView{img[c].px.data(), static_cast<uint16_t>(img[c].width), static_cast<uint16_t>(img[c].height),
                        static_cast<uint32_t>(img[c].width)};
  }
  if (match_clipping_) {  // on the sensor's pixels, where they clipped
    ClipStats st[2];
    uint8_t ceiling[2];
    for (int c = 0; c < 2; ++c) clip_stats(view[c], st[c]);
    match_clip_ceilings(st[0], st[1], ceiling);
    for (int c = 0; c < 2; ++c) {
      if (ceiling[c] == 255) continue;
      clamp_pixels(img[c].px.data(), view[c].width, view[c].height, view[c].stride, ceiling[c]);
      ++clamped_[c];
      int low = lowest_ceiling_[c].load();
      while (ceiling[c] < low && !lowest_ceiling_[c].compare_exchange_weak(low, ceiling[c])) {
      }
    }
  }
  for (int c = 0; c < 2; ++c) {
    if (remap_[c]) {
      std::vector<uint8_t> pinhole(img[c].px.size());
      remap_[c]->apply(img[c].px.data(), pinhole.data());
      img[c].px.swap(pinhole);
      view[c].pixels = img[c].px.data();
    }
    if (!bin_area(view[c], slot.px[c].data(), width_, height_))
      throw RecordingError(frame_of(c) + shown_path(f.path[c]) + ": cannot bin to the working resolution");
  }
}

void FileStereoCamera::worker() {
  for (;;) {
    size_t index;
    Slot* slot;
    {
      std::unique_lock<std::mutex> lock(mu_);
      slot_free_.wait(lock, [this] {
        return stop_ || next_job_ >= rec_.frames.size() || next_job_ < next_out_ + slots_.size();
      });
      if (stop_ || next_job_ >= rec_.frames.size()) return;
      index = next_job_++;
      slot = &slots_[index % slots_.size()];
    }
    // The slot is ours until the consumer has taken frame `index`.
    std::string problem;
    try {
      decode_into(index, *slot);
    } catch (const std::exception& e) {
      problem = e.what();
    }
    {
      std::lock_guard<std::mutex> lock(mu_);
      slot->index = index;
      slot->error = std::move(problem);
      slot->ready = true;
    }
    slot_ready_.notify_all();
  }
}

hal::CaptureStatus FileStereoCamera::capture(hal::StereoImage& out) {
  if (!error_.empty()) return hal::CaptureStatus::kError;
  if (next_out_ >= rec_.frames.size()) return hal::CaptureStatus::kEnd;
  Slot& slot = slots_[next_out_ % slots_.size()];
  {
    std::unique_lock<std::mutex> lock(mu_);
    slot_ready_.wait(lock, [&] { return slot.ready && slot.index == next_out_; });
    if (!slot.error.empty()) {
      error_ = slot.error;
      stop_ = true;  // the run ends here; let the workers go
      lock.unlock();
      slot_free_.notify_all();
      return hal::CaptureStatus::kError;
    }
  }
  // Workers never touch this slot until next_out_ moves past it.
  const size_t n = static_cast<size_t>(width_) * height_;
  std::memcpy(out.cam[0], slot.px[0].data(), n);
  std::memcpy(out.cam[1], slot.px[1].data(), n);
  out.t_ns = rec_.frames[next_out_].t_ns;
  out.width = width_;
  out.height = height_;
  {
    std::lock_guard<std::mutex> lock(mu_);
    slot.ready = false;
    ++next_out_;
  }
  slot_free_.notify_all();
  return hal::CaptureStatus::kOk;
}

}  // namespace lumavel::host
