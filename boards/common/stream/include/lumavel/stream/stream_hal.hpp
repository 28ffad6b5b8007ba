// HAL drivers over a recorded stream (format.hpp): one reader feeds the
// camera, the gyro and the host's feature requests, in the recorded order.
// Fixed memory, no heap, integer only: the same code runs in QEMU and on the host.
#pragma once
#include <cstddef>
#include <cstdint>

#include "lumavel/hal/camera.hpp"
#include "lumavel/hal/clock.hpp"
#include "lumavel/hal/config_store.hpp"
#include "lumavel/hal/gyro.hpp"
#include "lumavel/hal/report_link.hpp"
#include "lumavel/hal/watchdog.hpp"
#include "lumavel/protocol/descriptor.hpp"
#include "lumavel/protocol/device_config.hpp"
#include "lumavel/stream/byte_io.hpp"

namespace lumavel::stream {

enum class StreamError : uint8_t { kNone, kBadHeader, kTruncated, kBadTag, kBadRequest, kTooLarge };
const char* to_string(StreamError e);

class StreamReader {
 public:
  static constexpr int kGyroFifo = 64;
  static constexpr int kRequestQueue = 4;

  explicit StreamReader(ByteSource& src) : src_(src) {}
  // Reads the header. False (error() says why) if it is not a stream.
  bool open();
  uint16_t width() const { return width_; }
  uint16_t height() const { return height_; }

  // Reads records until the next frame (into cam0/cam1); gyro samples and
  // feature requests met on the way are queued. False at end or on error.
  bool next_frame(uint64_t& t_ns, uint8_t* cam0, uint8_t* cam1);
  // The next gyro sample: from the queue, else the next record if it is one.
  bool next_gyro(hal::GyroSample& out);

  struct Request {
    uint8_t id;
    bool is_set;
    uint8_t len;
    uint8_t data[protocol::kMaxReportSize];
  };
  bool pop_request(Request& out);

  StreamError error() const { return error_; }
  uint32_t record_index() const { return records_; }  // for error messages
  uint32_t gyro_dropped() const { return gyro_dropped_; }

 private:
  bool read_exact(uint8_t* buf, size_t len);
  int peek_tag();  // -1 at end of file
  bool read_gyro_body(hal::GyroSample& out);
  bool read_request(bool is_set);
  void queue_gyro(const hal::GyroSample& s);

  ByteSource& src_;
  uint16_t width_ = 0;
  uint16_t height_ = 0;
  int peeked_ = -2;  // -2: nothing peeked
  StreamError error_ = StreamError::kNone;
  uint32_t records_ = 0;
  hal::GyroSample gyro_[kGyroFifo]{};
  int gyro_head_ = 0;
  int gyro_count_ = 0;
  uint32_t gyro_dropped_ = 0;
  Request requests_[kRequestQueue]{};
  int req_head_ = 0;
  int req_count_ = 0;
};

class StreamCamera final : public hal::StereoCamera {
 public:
  explicit StreamCamera(StreamReader& r) : r_(r) {}
  uint16_t width() const override { return r_.width(); }
  uint16_t height() const override { return r_.height(); }
  hal::CaptureStatus capture(hal::StereoImage& out) override;
  uint64_t last_frame_ns() const { return last_ns_; }

 private:
  StreamReader& r_;
  uint64_t last_ns_ = 0;
};

class StreamGyro final : public hal::Gyro {
 public:
  explicit StreamGyro(StreamReader& r) : r_(r) {}
  bool read(hal::GyroSample& out) override;

 private:
  StreamReader& r_;
};

// Input reports and feature replies go to the sink, framed as in format.hpp.
class StreamReportLink final : public hal::ReportLink {
 public:
  StreamReportLink(StreamReader& r, ByteSink& out) : r_(r), out_(out) {}
  bool send_input(const uint8_t* report, size_t len) override;
  void poll_features(FeatureHandler handler, void* ctx) override;
  bool write_failed() const { return failed_; }

 private:
  bool emit(uint8_t kind, const uint8_t* bytes, size_t len);
  StreamReader& r_;
  ByteSink& out_;
  bool failed_ = false;
};

// Recorded time: the clock reads the last frame's timestamp, so runs are
// reproducible (and bit-identical between QEMU and the host).
class StreamClock final : public hal::Clock {
 public:
  explicit StreamClock(const StreamCamera& cam) : cam_(cam) {}
  uint64_t now_ns() override { return cam_.last_frame_ns(); }

 private:
  const StreamCamera& cam_;
};

// Configuration blob kept in RAM for the run (empty at start).
class RamConfigStore final : public hal::ConfigStore {
 public:
  size_t load(uint8_t* buf, size_t cap) override;
  bool save(const uint8_t* buf, size_t len) override;

 private:
  uint8_t blob_[protocol::kMaxStoredConfigSize]{};  // configuration report + lens tables
  size_t len_ = 0;
};

class CountingWatchdog final : public hal::Watchdog {
 public:
  void kick() override { ++kicks_; }
  uint32_t kicks() const { return kicks_; }

 private:
  uint32_t kicks_ = 0;
};

}  // namespace lumavel::stream
