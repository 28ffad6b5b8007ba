// Where decoded input reports go: CSV (stdout or file), the live terminal
// line, and the bookkeeping of lost (sequence gaps), duplicated (a sequence
// number seen again) and malformed reports.
#pragma once
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <deque>
#include <string>

#include "lumavel/protocol/reports.hpp"

namespace lumavel::read {

class Sink {
 public:
  // csv may be null (live view only); live draws on stderr... on the terminal.
  // from_file: the reports of a report file, which holds every report its run
  // sent: a sequence gap or a step back there is a damaged file, counted as
  // malformed, not a loss on a live link.
  Sink(std::FILE* csv, bool live, bool from_file = false);
  ~Sink();
  // Decodes one input report; `where` names it in messages. True if it was a measurement.
  bool take(const uint8_t* buf, size_t len, const std::string& where);
  void restart_sequence() { have_seq_ = false; }
  void finish();
  uint64_t measurements() const { return count_; }
  uint64_t malformed() const { return malformed_; }
  uint64_t lost() const { return lost_; }
  uint64_t duplicated() const { return duplicated_; }

 private:
  void draw(const protocol::Measurement& m);

  std::FILE* csv_;
  bool live_, from_file_;
  bool have_seq_ = false;
  uint16_t next_seq_ = 0;
  protocol::Measurement last_{};  // the last measurement taken (a report file's order is checked against it)
  uint64_t count_ = 0, malformed_ = 0, lost_ = 0, duplicated_ = 0;
  std::deque<std::chrono::steady_clock::time_point> window_;
  std::chrono::steady_clock::time_point last_draw_{};
};

}  // namespace lumavel::read
