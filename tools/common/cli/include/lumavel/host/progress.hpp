// Progress of a long command on stderr: on a terminal a one-line bar redrawn
// about 10 times a second; otherwise (a pipe, a log file) one line every few
// seconds, so that a piped run is not silent for minutes either.
#pragma once
#include <chrono>
#include <string>

namespace lumavel::cli {

class Progress {
 public:
  // `total` units of work; `label` starts every line ("render", "calibrate: reading frames").
  Progress(long total, std::string label, double line_every_s = 5.0);
  void update(long done);  // cheap: draws only when it is time
  void finish();           // the last state, then a new line (terminal) or a final line

 private:
  void draw(long done, std::chrono::steady_clock::time_point now);

  long total_;
  std::string label_;
  bool terminal_;
  std::chrono::duration<double> every_;
  std::chrono::steady_clock::time_point start_, last_;
  long last_done_ = -1;
};

}  // namespace lumavel::cli
