#include "lumavel/host/progress.hpp"

#include <unistd.h>

#include <cstdio>

namespace lumavel::cli {

Progress::Progress(long total, std::string label, double line_every_s)
    : total_(total > 0 ? total : 1),
      label_(std::move(label)),
      terminal_(isatty(STDERR_FILENO) != 0),
      every_(terminal_ ? 0.1 : line_every_s),
      start_(std::chrono::steady_clock::now()),
      last_(start_) {}

void Progress::update(long done) {
  const auto now = std::chrono::steady_clock::now();
  if (now - last_ < every_) return;
  last_ = now;
  draw(done, now);
}

void Progress::draw(long done, std::chrono::steady_clock::time_point now) {
  last_done_ = done;
  const double f = static_cast<double>(done) / static_cast<double>(total_);
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  const double left = done > 0 ? elapsed * (static_cast<double>(total_ - done) / static_cast<double>(done)) : 0;
  if (terminal_) {
    constexpr int kWidth = 40;
    std::string bar(static_cast<size_t>(f * kWidth), '#');
    bar.resize(kWidth, '.');
    std::fprintf(stderr, "\r%s [%s] %ld/%ld  %.0fs elapsed, %.0fs left ", label_.c_str(), bar.c_str(), done, total_,
                 elapsed, left);
  } else {
    std::fprintf(stderr, "%s: %ld/%ld (%.0f %%), %.0f s elapsed, about %.0f s left\n", label_.c_str(), done, total_,
                 100 * f, elapsed, left);
  }
  std::fflush(stderr);
}

void Progress::finish() {
  const auto now = std::chrono::steady_clock::now();
  if (terminal_) {
    draw(total_, now);
    std::fputc('\n', stderr);
  } else if (last_done_ >= 0) {  // lines were printed: say it ended
    std::fprintf(stderr, "%s: %ld/%ld done in %.0f s\n", label_.c_str(), total_, total_,
                 std::chrono::duration<double>(now - start_).count());
  }
}

}  // namespace lumavel::cli
