#include "lumavel/host/render/progress_bar.hpp"

#include <unistd.h>

namespace lumavel::host::render {

ProgressBar::ProgressBar(long total, std::string label)
    : total_(total > 0 ? total : 1),
      label_(std::move(label)),
      enabled_(isatty(STDERR_FILENO) != 0),
      start_(std::chrono::steady_clock::now()),
      last_(start_ - std::chrono::seconds(1)) {}

void ProgressBar::update(long done) {
  if (!enabled_) return;
  const auto now = std::chrono::steady_clock::now();
  if (done < total_ && now - last_ < std::chrono::milliseconds(100)) return;
  last_ = now;
  constexpr int kWidth = 40;
  const double f = static_cast<double>(done) / static_cast<double>(total_);
  const int fill = static_cast<int>(f * kWidth);
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  const double eta = done > 0 ? elapsed * (static_cast<double>(total_ - done) / static_cast<double>(done)) : 0;
  std::string bar(static_cast<size_t>(fill), '#');
  bar.resize(kWidth, '.');
  std::fprintf(stderr, "\r%s [%s] %ld/%ld  %.0fs elapsed, %.0fs left ", label_.c_str(), bar.c_str(),
               done, total_, elapsed, eta);
  std::fflush(stderr);
}

void ProgressBar::finish() {
  if (!enabled_) return;
  update(total_);
  std::fputc('\n', stderr);
}

}  // namespace lumavel::host::render
