// A one-line progress bar on stderr, drawn only when stderr is a terminal.
#pragma once
#include <chrono>
#include <cstdio>
#include <string>

namespace lumavel::host::render {

class ProgressBar {
 public:
  ProgressBar(long total, std::string label);
  void update(long done);  // cheap; redraws at most ~10 times a second
  void finish();

 private:
  long total_;
  std::string label_;
  bool enabled_;
  std::chrono::steady_clock::time_point start_, last_;
};

}  // namespace lumavel::host::render
