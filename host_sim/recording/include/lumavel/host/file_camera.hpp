// hal::StereoCamera over a recording: delivers the frame pairs in order,
// binned to the working resolution with lumavel::bin_area, like a board driver
// bins its sensor. With `undistort`, a camera whose sensor.yaml gives a lens
// distortion has every frame resampled onto the pinhole of its intrinsics
// first (lens_remap.hpp): the working frames are then pinhole frames. With
// `match_clipping`, the camera that clips less is clamped where the other
// clips (clip_match.hpp), on the sensor's pixels, before both. A pair in
// which one camera repeats the frame it gave before (the same pixels as read)
// while the other's moved on is skipped as a dropped one (not a plain frame,
// nor a repeat after the first in a row: a stuck camera). Frames are
// decoded ahead on a small thread pool so a run is limited by the estimator,
// not by PNG decoding.
#pragma once
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "lumavel/hal/camera.hpp"
#include "lumavel/host/lens_remap.hpp"
#include "lumavel/host/recording.hpp"

namespace lumavel::host {

// What is done to the sensor's frames before they are binned.
struct FrameProcessing {
  bool undistort = false;       // onto the pinhole of the intrinsics (lens_remap.hpp)
  bool match_clipping = false;  // clamp the camera that clips less where the other clips (clip_match.hpp)
};

class FileStereoCamera : public hal::StereoCamera {
 public:
  // `rec` must outlive the camera. Throws RecordingError when the recording's
  // frames cannot be binned to width x height.
  FileStereoCamera(const Recording& rec, int width, int height, int threads = 2, int lookahead = 16,
                   FrameProcessing processing = {});
  ~FileStereoCamera() override;
  FileStereoCamera(const FileStereoCamera&) = delete;
  FileStereoCamera& operator=(const FileStereoCamera&) = delete;

  uint16_t width() const override { return width_; }
  uint16_t height() const override { return height_; }
  // kOk with the next pair; kEnd after the last; kError for a bad frame
  // (wrong size or depth, truncated, corrupt): error() names file and frame.
  hal::CaptureStatus capture(hal::StereoImage& out) override;

  const std::string& error() const { return error_; }
  // Pixels of camera c's pinhole view outside its sensor (a pincushion lens;
  // they repeat the edge): 0 without undistortion or with a barrel lens.
  int pinhole_outside(int c) const { return remap_[c] ? remap_[c]->outside() : 0; }
  // Frames of camera c clamped at a clip ceiling below 255, and the lowest one
  // (255 when none was).
  size_t frames_clamped(int c) const { return clamped_[c].load(); }
  int lowest_ceiling(int c) const { return lowest_ceiling_[c].load(); }
  // Pairs skipped because camera c's frame, as read, repeated the one it had
  // delivered last while the other camera's moved on, and the first one's
  // index in rec.frames (capture(): a repeated frame reads as that camera
  // standing still, i.e. as motion of the other).
  size_t frames_repeated(int c) const { return repeats_[c]; }
  size_t first_repeated(int c) const { return first_repeat_[c]; }
  size_t frames_delivered() const { return next_out_; }
  size_t frame_count() const { return rec_.frames.size(); }

 private:
  struct Slot {
    std::vector<uint8_t> px[2];
    uint64_t raw_hash[2] = {0, 0};  // of each camera's frame as read, before any processing
    bool plain[2] = {false, false};  // every pixel of it alike
    size_t index = 0;
    bool ready = false;
    std::string error;
  };
  void worker();
  void decode_into(size_t index, Slot& slot) const;

  const Recording& rec_;
  uint16_t width_, height_;
  std::unique_ptr<LensRemap> remap_[2];  // null: the frames are binned as they are
  bool match_clipping_;
  mutable std::atomic<size_t> clamped_[2] = {};          // (decode_into runs on several threads)
  mutable std::atomic<int> lowest_ceiling_[2] = {255, 255};
  std::vector<Slot> slots_;
  std::vector<std::thread> threads_;
  std::mutex mu_;
  std::condition_variable slot_ready_;  // a worker filled a slot
  std::condition_variable slot_free_;   // the consumer released a slot
  size_t next_job_ = 0;                 // next frame index a worker takes
  uint64_t prev_hash_[2] = {0, 0};      // of the frames delivered last, as read (the consumer's)
  size_t repeat_run_[2] = {0, 0};       // frames in a row camera c gave the same pixels as the one delivered last
  size_t repeats_[2] = {0, 0}, first_repeat_[2] = {0, 0};
  size_t next_out_ = 0;                 // next frame index capture() returns
  bool stop_ = false;
  std::string error_;
};

}  // namespace lumavel::host
