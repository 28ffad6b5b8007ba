// The stream tools' numeric arguments, read as lumavel-sim's and
// lumavel-read's options are (decimal_text.hpp's read_whole): std::atoi read
// "40x" as 40 and 4294967336 as 40 (it wraps to int), and the tool ran on,
// exit 0, the mistake unsaid.
#pragma once
#include <cstdio>
#include <string>

#include "lumavel/host/decimal_text.hpp"
#include "lumavel/host/path_check.hpp"

namespace lumavel::stream {

// `text`, the argument `name`, as a whole number in lo..hi into `out`; or
// false after saying why on standard error, "PROG: width: must be a whole
// number in 16..2048, not '40x'", for the caller's usage exit (2).
inline bool whole_argument(const char* prog, const char* name, const char* text, long long lo, long long hi,
                           long long& out) {
  const host::WholeText w = host::read_whole(text);
  if (w.problem == host::WholeText::Problem::kNone && w.value >= lo && w.value <= hi) {
    out = w.value;
    return true;
  }
  std::fprintf(stderr, "%s: %s: must be a whole number in %lld..%lld, not '%s'\n", prog, name, lo, hi,
               host::shown_path(text).c_str());
  return false;
}

// `text`, the path argument `name`, is not empty; or false after saying so on
// standard error, "PROG: out.lvs: needs a path, not an empty one" (as
// lumavel-sim's and lumavel-read's path options say it), for the caller's
// usage exit (2). An empty output name was taken by OutputFile for standard
// output: the binary stream went to the terminal, exit 0, summarised as
// ': 60 frames at 40x30'.
inline bool path_argument(const char* prog, const char* name, const char* text) {
  if (text[0] != '\0') return true;
  std::fprintf(stderr, "%s: %s: needs a path, not an empty one\n", prog, name);
  return false;
}

// The stream file `text` (the argument `name`) can be written; or false after
// saying why on standard error, as lumavel-sim's outputs say it: "PROG: - 
// (out.lvs): '-' stands for standard output, where no stream file is
// written: ...", "PROG: nodir/x.lvs (out.lvs): cannot be created: its folder
// nodir does not exist", for the caller's failure exit (1). '-' made a file
// of that name in the current folder, exit 0 (render, import-slider and
// calibrate --write refuse it), and a missing folder was said as 'cannot
// create the stream: No such file or directory'.
inline bool output_argument(const char* prog, const char* name, const char* text) {
  const std::string why = host::why_not_writable(text, "stream file");
  if (why.empty()) return true;
  std::fprintf(stderr, "%s: %s (%s): %s\n", prog, host::shown_path(text).c_str(), name, why.c_str());
  return false;
}

}  // namespace lumavel::stream
