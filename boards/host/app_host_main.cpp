// Host build of the firmware app: runs the same App over the same stream code
// as the QEMU firmware, with host files as the byte source and sink.
//   lumavel_app_host <in.lvs> <out.lvr>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <system_error>

#include "lumavel/core/limits.hpp"
#include "lumavel/stream/run_stream.hpp"

namespace {

class FileSource final : public lumavel::stream::ByteSource {
 public:
  explicit FileSource(std::FILE* f) : f_(f) {}
  size_t read(uint8_t* buf, size_t len) override { return std::fread(buf, 1, len, f_); }

 private:
  std::FILE* f_;
};

class FileSink final : public lumavel::stream::ByteSink {
 public:
  explicit FileSink(std::FILE* f) : f_(f) {}
  bool write(const uint8_t* buf, size_t len) override { return std::fwrite(buf, 1, len, f_) == len; }

 private:
  std::FILE* f_;
};

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: %s <in.lvs> <out.lvr>\n", argv[0]);
    return 1;
  }
  // An empty name was said as nothing: ': cannot open for reading: No such
  // file or directory'. Now as the stream tools say it (usage, exit 1 here).
  for (int i = 1; i <= 2; ++i)
    if (argv[i][0] == '\0') {
      std::fprintf(stderr, "%s: %s: needs a path, not an empty one\n", argv[0], i == 1 ? "in.lvs" : "out.lvr");
      return 1;
    }
  // '-' made a file of that name in the current folder, exit 0 (the stream
  // tools and lumavel-sim refuse it; boards may not include their path checks).
  for (int i = 1; i <= 2; ++i)
    if (std::strcmp(argv[i], "-") == 0) {
      std::fprintf(stderr, "%s: - (%s): '-' stands for standard %s, which this tool does not use: give a file name "
                   "(./- for a file of that name)\n", argv[0], i == 1 ? "in.lvs" : "out.lvr", i == 1 ? "input" : "output");
      return 1;
    }
  // The results written over the stream being read (or a link to it)
  // truncated it before its first byte was read: the input lost, and said
  // as 'record 0: not a lumavel stream (bad header)'.
  std::error_code ec;
  if (std::filesystem::equivalent(argv[1], argv[2], ec) && !ec) {
    std::fprintf(stderr, "%s: that is the stream being read (%s): write the results elsewhere\n", argv[2], argv[1]);
    return 1;
  }
  std::FILE* in = std::fopen(argv[1], "rb");
  if (in == nullptr) {
    std::fprintf(stderr, "%s: cannot open for reading: %s\n", argv[1], std::strerror(errno));
    return 1;
  }
  std::FILE* out = std::fopen(argv[2], "wb");
  if (out == nullptr) {
    std::fprintf(stderr, "%s: cannot open for writing: %s\n", argv[2], std::strerror(errno));
    std::fclose(in);
    return 1;
  }
  FileSource src(in);
  FileSink sink(out);
  const lumavel::stream::RunSummary s = lumavel::stream::run_stream(src, sink, lumavel::stream::kStreamBoardName);
  // A stream that could not be read (a folder: fopen takes it, fread fails)
  // is said as such, not as the damaged stream its missing bytes look like.
  const int read_errno = std::ferror(in) ? errno : 0;
  std::fclose(in);
  const bool closed = std::fclose(out) == 0;
  const auto& c = s.counters;
  std::fprintf(stderr, "frames %u, overruns %u, capture errors %u, gyro samples %u, feature requests %u, "
               "watchdog kicks %u\n", c.frames, c.overruns, c.capture_errors, c.gyro_samples,
               c.feature_requests, s.watchdog_kicks);
  // The stream's gyro samples beyond what the FIFO holds between two frames
  // are lost, oldest first, as a sensor's FIFO overflows (was: unsaid, exit 0:
  // a 476 kHz gyro's 944578 samples ran as 7800, 'capture errors 0').
  if (s.gyro_dropped > 0)
    std::fprintf(stderr,
                 "%s: warning: %u of its gyro samples dropped: more came between two frames than the gyro FIFO holds "
                 "(%d samples; the oldest lost, as a sensor's FIFO overflows), so the estimates saw only the newest "
                 "of each interval\n",
                 argv[1], s.gyro_dropped, lumavel::stream::StreamReader::kGyroFifo);
  switch (s.outcome) {
    case lumavel::stream::RunOutcome::kOk:
      return closed ? 0 : 1;
    case lumavel::stream::RunOutcome::kBadStream:
      if (read_errno != 0) {
        std::fprintf(stderr, "%s: read error: %s\n", argv[1], std::strerror(read_errno));
        return 2;
      }
      std::fprintf(stderr, "%s: record %u: %s", argv[1], s.record_index, lumavel::stream::to_string(s.stream_error));
      // (the size, which "frame larger than the build's capacity" leaves unsaid)
      if (s.stream_error == lumavel::stream::StreamError::kTooLarge)
        std::fprintf(stderr, ": its header says %ux%u pixels, this build takes at most %dx%d", unsigned{s.width},
                     unsigned{s.height}, lumavel::kMaxColumns, lumavel::kMaxRows);
      std::fprintf(stderr, "\n");
      return 2;
    case lumavel::stream::RunOutcome::kUnconfigured:
      std::fprintf(stderr, "%s: no configuration accepted (%s)\n", argv[1],
                   lumavel::protocol::to_string(s.config_status));
      return 3;
    case lumavel::stream::RunOutcome::kWriteFailed:
      std::fprintf(stderr, "%s: write failed\n", argv[2]);
      return 4;
  }
  return 1;
}
