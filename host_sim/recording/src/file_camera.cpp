#include "lumavel/host/file_camera.hpp"

#include <algorithm>
#include <cstring>

#include "lumavel/core/binning.hpp"
#include "lumavel/core/clip_match.hpp"
#include "lumavel/host/image_io.hpp"
#include "lumavel/host/path_check.hpp"
#include "lumavel/host/recording_layout.hpp"
#include "lumavel/host/rig.hpp"

namespace lumavel::host {
namespace {

// FNV-1a over a frame's pixels as read: a frame that repeats the one before
// hashes alike whatever the clip match or the binning then make of it.
uint64_t pixel_hash(const std::vector<uint8_t>& px) {
  uint64_t h = 1469598103934665603ull;
  for (uint8_t v : px) h = (h ^ v) * 1099511628211ull;
  return h;
}

}  // namespace

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
    slot.raw_hash[c] = pixel_hash(img[c].px);
    slot.plain[c] = std::all_of(img[c].px.begin(), img[c].px.end(), [&](uint8_t v) { return v == img[c].px.front(); });
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
  const size_t n = static_cast<size_t>(width_) * height_;
  for (;;) {
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
    // Workers never touch this slot until next_out_ moves past it. One camera's
    // frame, as read, the same pixels as the one it delivered last, while the
    // other's moved on: that camera repeated a frame (a driver read it twice).
    // The pair is skipped, as a dropped one (both alike: a still scene). Not
    // a plain frame (a covered lens), nor a second repeat in a row (a camera
    // that gives one frame on and on is motion_direction.hpp's still camera).
    bool same[2] = {false, false};
    if (next_out_ > 0)
      for (int c = 0; c < 2; ++c) same[c] = slot.raw_hash[c] == prev_hash_[c];
    for (int c = 0; c < 2; ++c) repeat_run_[c] = same[c] ? repeat_run_[c] + 1 : 0;
    const int c_rep = same[0] ? 0 : 1;
    const bool repeated = same[0] != same[1] && !slot.plain[c_rep] && repeat_run_[c_rep] == 1;
    if (repeated) {
      if (repeats_[c_rep]++ == 0) first_repeat_[c_rep] = next_out_;
    } else {
      std::memcpy(out.cam[0], slot.px[0].data(), n);
      std::memcpy(out.cam[1], slot.px[1].data(), n);
      for (int c = 0; c < 2; ++c) prev_hash_[c] = slot.raw_hash[c];
      out.t_ns = rec_.frames[next_out_].t_ns;
      out.width = width_;
      out.height = height_;
    }
    {
      std::lock_guard<std::mutex> lock(mu_);
      slot.ready = false;
      ++next_out_;
    }
    slot_free_.notify_all();
    if (!repeated) return hal::CaptureStatus::kOk;
  }
}

}  // namespace lumavel::host
