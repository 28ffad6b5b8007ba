#include "sensors.hpp"

namespace bluepill {

void MpuGyro::poll() {
  if (!present_) return;
  lumavel::hal::GyroSample s[16];
  const size_t free = static_cast<size_t>(kRing - count_);
  const size_t n = mpu_.poll(bus_, clock_.now_ns(), s, free < 16 ? free : 16);
  for (size_t i = 0; i < n; ++i) {
    ring_[(head_ + count_) % kRing] = s[i];
    ++count_;
  }
}

bool MpuGyro::read(lumavel::hal::GyroSample& out) {
  if (count_ == 0) poll();
  if (count_ == 0) return false;
  out = ring_[head_];
  head_ = (head_ + 1) % kRing;
  --count_;
  return true;
}

void TslCamera::init() {
  port_.init();
  lumavel::bluepill::tsl1401_flush(port_);  // clears power-up charge, starts integrating
  start_ns_ = clock_.now_ns();
}

lumavel::hal::CaptureStatus TslCamera::capture(lumavel::hal::StereoImage& out) {
  if (out.width != width() || out.height != height()) return lumavel::hal::CaptureStatus::kError;
  while (clock_.now_ns() - start_ns_ < kExposureNs) idle_(ctx_);
  const uint64_t end = clock_.now_ns();
  // The read-out's SI pulse ends this integration and starts the next.
  lumavel::bluepill::tsl1401_read(port_, out.cam[0], out.cam[1]);
  out.t_ns = start_ns_ + (end - start_ns_) / 2;  // middle of the exposure
  start_ns_ = end;
  return lumavel::hal::CaptureStatus::kOk;
}

}  // namespace bluepill
