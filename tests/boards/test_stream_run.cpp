// The stream boards' runner (boards/common/stream: the QEMU firmware and the
// host build of the app, lumavel_app_host) on damaged streams: each run ends,
// naming the record and why, never retries for ever. A truncated record or an
// unknown tag was a capture error, which the app retries (a camera's glitch
// passes; a stream's damage does not): the run hung at its first damaged
// record. CTest's TIMEOUT fails a hang.
#include <CppUTest/TestHarness.h>

#include <cstdint>
#include <algorithm>
#include <cstring>
#include <utility>
#include <vector>

#include "lumavel/stream/format.hpp"
#include "lumavel/stream/run_stream.hpp"

namespace stream = lumavel::stream;

namespace {

class MemorySource final : public stream::ByteSource {
 public:
  explicit MemorySource(std::vector<uint8_t> bytes) : bytes_(std::move(bytes)) {}
  size_t read(uint8_t* buf, size_t len) override {
    const size_t n = std::min(len, bytes_.size() - pos_);
    std::memcpy(buf, bytes_.data() + pos_, n);
    pos_ += n;
    return n;
  }

 private:
  std::vector<uint8_t> bytes_;
  size_t pos_ = 0;
};

class NullSink final : public stream::ByteSink {
 public:
  bool write(const uint8_t*, size_t) override { return true; }
};

constexpr uint16_t kWidth = 40, kHeight = 30;

// A stream: its header, then `frames` pairs of a gyro sample and a frame, at 60 Hz.
std::vector<uint8_t> stream_of(int frames) {
  std::vector<uint8_t> s = {'L', 'V', 'S', '1', kWidth, 0, kHeight, 0};
  const auto u64 = [&](uint64_t v) {
    for (int i = 0; i < 8; ++i) s.push_back(static_cast<uint8_t>(v >> (8 * i)));
  };
  for (int k = 0; k < frames; ++k) {
    const uint64_t t = 100000000 + static_cast<uint64_t>(k) * 16666667;
    s.push_back(stream::kTagGyro);
    u64(t);
    for (int i = 0; i < 4; ++i) s.push_back(0);
    s.push_back(stream::kTagFrame);
    u64(t);
    for (int i = 0; i < 2 * kWidth * kHeight; ++i) s.push_back(static_cast<uint8_t>(i * 7 + k * 3));
  }
  return s;
}

stream::RunSummary run_over(std::vector<uint8_t> bytes) {
  MemorySource in(std::move(bytes));
  NullSink out;
  return stream::run_stream(in, out, stream::kStreamBoardName);
}

}  // namespace

TEST_GROUP(StreamRun) {};

TEST(StreamRun, AnIntactStreamRunsToItsEnd) {
  const stream::RunSummary s = run_over(stream_of(5));
  CHECK(s.outcome == stream::RunOutcome::kOk);
  LONGS_EQUAL(5, s.counters.frames);
}

TEST(StreamRun, AStreamCutInsideARecordEndsNamingTheRecord) {
  std::vector<uint8_t> cut = stream_of(5);
  cut.resize(8 + 5);  // the header, then 5 bytes of the first gyro record
  stream::RunSummary s = run_over(cut);
  CHECK(s.outcome == stream::RunOutcome::kBadStream);
  CHECK(s.stream_error == stream::StreamError::kTruncated);
  LONGS_EQUAL(1, s.record_index);

  cut = stream_of(5);
  cut.resize(cut.size() - 100);  // inside the last frame's pixels
  s = run_over(cut);
  CHECK(s.outcome == stream::RunOutcome::kBadStream);
  CHECK(s.stream_error == stream::StreamError::kTruncated);
  LONGS_EQUAL(10, s.record_index);
  LONGS_EQUAL(4, s.counters.frames);  // the intact frames before it were run
}

TEST(StreamRun, AnUnknownRecordTagEndsNamingTheRecord) {
  std::vector<uint8_t> bad = stream_of(5);
  bad.push_back('X');
  const stream::RunSummary s = run_over(bad);
  CHECK(s.outcome == stream::RunOutcome::kBadStream);
  CHECK(s.stream_error == stream::StreamError::kBadTag);
  LONGS_EQUAL(11, s.record_index);
  LONGS_EQUAL(5, s.counters.frames);
}
