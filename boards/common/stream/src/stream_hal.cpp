#include "lumavel/stream/stream_hal.hpp"

#include "lumavel/core/limits.hpp"
#include "lumavel/stream/format.hpp"

namespace lumavel::stream {
namespace {

uint64_t get_u64(const uint8_t* p) {
  uint64_t v = 0;
  for (int i = 7; i >= 0; --i) v = (v << 8) | p[i];
  return v;
}

uint32_t get_u32(const uint8_t* p) {
  return static_cast<uint32_t>(p[0]) | static_cast<uint32_t>(p[1]) << 8 |
         static_cast<uint32_t>(p[2]) << 16 | static_cast<uint32_t>(p[3]) << 24;
}

}  // namespace

const char* to_string(StreamError e) {
  switch (e) {
    case StreamError::kNone: return "no error";
    case StreamError::kBadHeader: return "not a lumavel stream (bad header)";
    case StreamError::kTruncated: return "truncated record";
    case StreamError::kBadTag: return "unknown record tag";
    case StreamError::kBadRequest: return "feature request longer than any report";
    case StreamError::kTooLarge: return "frame larger than the build's capacity";
  }
  return "?";
}

bool StreamReader::read_exact(uint8_t* buf, size_t len) {
  if (src_.read(buf, len) == len) return true;
  error_ = StreamError::kTruncated;
  return false;
}

int StreamReader::peek_tag() {
  if (peeked_ == -2) {
    uint8_t tag = 0;
    peeked_ = src_.read(&tag, 1) == 1 ? tag : -1;
  }
  return peeked_;
}

bool StreamReader::open() {
  uint8_t h[kHeaderSize];
  if (src_.read(h, sizeof h) != sizeof h || h[0] != kMagic[0] || h[1] != kMagic[1] ||
      h[2] != kMagic[2] || h[3] != kMagic[3]) {
    error_ = StreamError::kBadHeader;
    return false;
  }
  width_ = static_cast<uint16_t>(h[4] | h[5] << 8);
  height_ = static_cast<uint16_t>(h[6] | h[7] << 8);
  if (width_ == 0 || height_ == 0) {
    error_ = StreamError::kBadHeader;
    return false;
  }
  if (width_ > kMaxColumns || height_ > kMaxRows) {
    error_ = StreamError::kTooLarge;
    return false;
  }
  return true;
}

bool StreamReader::read_gyro_body(hal::GyroSample& out) {
  uint8_t b[kGyroBodySize];
  if (!read_exact(b, sizeof b)) return false;
  out.t_ns = get_u64(b);
  out.rate_z = static_cast<RateQ24>(get_u32(b + 8));
  return true;
}

void StreamReader::queue_gyro(const hal::GyroSample& s) {
  if (gyro_count_ == kGyroFifo) {  // a real sensor FIFO overflows the same way: oldest lost
    gyro_head_ = (gyro_head_ + 1) % kGyroFifo;
    --gyro_count_;
    ++gyro_dropped_;
  }
  gyro_[(gyro_head_ + gyro_count_) % kGyroFifo] = s;
  ++gyro_count_;
}

bool StreamReader::read_request(bool is_set) {
  Request r{};
  r.is_set = is_set;
  if (!read_exact(&r.id, 1)) return false;
  if (is_set) {
    if (!read_exact(&r.len, 1)) return false;
    if (r.len > sizeof r.data) {
      error_ = StreamError::kBadRequest;
      return false;
    }
    if (!read_exact(r.data, r.len)) return false;
  }
  if (req_count_ == kRequestQueue) {  // host sent more than the device serves per frame: oldest lost
    req_head_ = (req_head_ + 1) % kRequestQueue;
    --req_count_;
  }
  requests_[(req_head_ + req_count_) % kRequestQueue] = r;
  ++req_count_;
  return true;
}

bool StreamReader::next_frame(uint64_t& t_ns, uint8_t* cam0, uint8_t* cam1) {
  if (error_ != StreamError::kNone) return false;
  for (;;) {
    const int tag = peek_tag();
    if (tag < 0) return false;  // end of stream
    peeked_ = -2;
    ++records_;
    if (tag == kTagGyro) {
      hal::GyroSample s{};
      if (!read_gyro_body(s)) return false;
      queue_gyro(s);
    } else if (tag == kTagSetFeature || tag == kTagGetFeature) {
      if (!read_request(tag == kTagSetFeature)) return false;
    } else if (tag == kTagFrame) {
      uint8_t t[8];
      const size_t n = size_t{width_} * height_;
      if (!read_exact(t, sizeof t) || !read_exact(cam0, n) || !read_exact(cam1, n)) return false;
      t_ns = get_u64(t);
      return true;
    } else {
      error_ = StreamError::kBadTag;
      return false;
    }
  }
}

bool StreamReader::next_gyro(hal::GyroSample& out) {
  if (gyro_count_ > 0) {
    out = gyro_[gyro_head_];
    gyro_head_ = (gyro_head_ + 1) % kGyroFifo;
    --gyro_count_;
    return true;
  }
  // Only a gyro record that comes next is "ready"; a frame ahead of it is not consumed.
  if (error_ != StreamError::kNone || peek_tag() != kTagGyro) return false;
  peeked_ = -2;
  ++records_;
  return read_gyro_body(out);
}

bool StreamReader::pop_request(Request& out) {
  if (req_count_ == 0) return false;
  out = requests_[req_head_];
  req_head_ = (req_head_ + 1) % kRequestQueue;
  --req_count_;
  return true;
}

hal::CaptureStatus StreamCamera::capture(hal::StereoImage& out) {
  if (out.width != r_.width() || out.height != r_.height()) return hal::CaptureStatus::kError;
  uint64_t t = 0;
  // A damaged stream (a truncated record, an unknown tag) ends here too: no
  // later frame can be found in it. As a capture error, the app, which
  // retries a camera's glitch, retried for ever (the run hung); at its end,
  // run_stream reports the reader's error (kBadStream, record and why).
  if (!r_.next_frame(t, out.cam[0], out.cam[1])) return hal::CaptureStatus::kEnd;
  out.t_ns = t;
  last_ns_ = t;
  return hal::CaptureStatus::kOk;
}

bool StreamGyro::read(hal::GyroSample& out) { return r_.next_gyro(out); }

bool StreamReportLink::emit(uint8_t kind, const uint8_t* bytes, size_t len) {
  if (len > 255) return false;
  const uint8_t head[2] = {kind, static_cast<uint8_t>(len)};
  const bool ok = out_.write(head, 2) && out_.write(bytes, len);
  if (!ok) failed_ = true;
  return ok;
}

bool StreamReportLink::send_input(const uint8_t* report, size_t len) {
  return emit(kKindInput, report, len);
}

void StreamReportLink::poll_features(FeatureHandler handler, void* ctx) {
  StreamReader::Request r{};
  while (r_.pop_request(r)) {
    uint8_t buf[protocol::kMaxReportSize];
    size_t n = r.len;
    for (size_t i = 0; i < n; ++i) buf[i] = r.data[i];
    const size_t reply = handler(ctx, r.id, r.is_set, buf, n, sizeof buf);
    if (r.is_set) {
      const uint8_t accepted = reply != 0 ? 1 : 0;
      emit(kKindReply, &accepted, 1);
    } else {
      emit(kKindReply, buf, reply <= sizeof buf ? reply : 0);
    }
  }
}

size_t RamConfigStore::load(uint8_t* buf, size_t cap) {
  if (len_ > cap) return 0;
  for (size_t i = 0; i < len_; ++i) buf[i] = blob_[i];
  return len_;
}

bool RamConfigStore::save(const uint8_t* buf, size_t len) {
  if (len > sizeof blob_) return false;
  for (size_t i = 0; i < len; ++i) blob_[i] = buf[i];
  len_ = len;
  return true;
}

}  // namespace lumavel::stream
