#include "lumavel/host/recording_error.hpp"

namespace lumavel::host {

RecordingError recording_error_at(const std::string& file, long line, const std::string& what) {
  // Line 0: a value not read from a file (CameraSensor::Lines), e.g. the
  // sensor.yaml a render is about to write: the file alone.
  if (line <= 0) return recording_error_in(file, what);
  return RecordingError(file + ":" + std::to_string(line) + ": " + what);
}

RecordingError recording_error_in(const std::string& file, const std::string& what) {
  return RecordingError(file + ": " + what);
}

}  // namespace lumavel::host
