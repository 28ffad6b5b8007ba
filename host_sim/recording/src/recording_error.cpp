#include "lumavel/host/recording_error.hpp"

#include "lumavel/host/path_check.hpp"

namespace lumavel::host {

// The file through shown_path, here for every refusal: its name is given on
// the command line or made from a table's field, and the readers put it in as
// it was (was: a recording folder named 'e<ESC>[2Jrec' cleared the terminal
// with '.../imu0/data.csv:5: ...', though its frames' names were escaped).
RecordingError recording_error_at(const std::string& file, long line, const std::string& what) {
  // Line 0: a value not read from a file (CameraSensor::Lines), e.g. the
  // sensor.yaml a render is about to write: the file alone.
  if (line <= 0) return recording_error_in(file, what);
  return RecordingError(shown_path(file) + ":" + std::to_string(line) + ": " + what);
}

RecordingError recording_error_in(const std::string& file, const std::string& what) {
  return RecordingError(shown_path(file) + ": " + what);
}

}  // namespace lumavel::host
