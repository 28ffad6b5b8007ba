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

}  // namespace lumavel::stream
