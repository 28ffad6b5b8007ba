// The one exception type for bad recordings: its message always names the
// file and, where it applies, the line or frame.
#pragma once
#include <stdexcept>
#include <string>

namespace lumavel::host {

class RecordingError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// "FILE:LINE: what" (LINE is 1-based, the header is line 1), FILE as
// shown_path shows it (control characters as \xNN, a long path shortened):
// callers pass the path as it is.
RecordingError recording_error_at(const std::string& file, long line, const std::string& what);
// "FILE: what"
RecordingError recording_error_in(const std::string& file, const std::string& what);

}  // namespace lumavel::host
