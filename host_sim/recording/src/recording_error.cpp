#include "lumavel/host/recording_error.hpp"

namespace lumavel::host {

RecordingError recording_error_at(const std::string& file, long line, const std::string& what) {
  return RecordingError(file + ":" + std::to_string(line) + ": " + what);
}

RecordingError recording_error_in(const std::string& file, const std::string& what) {
  return RecordingError(file + ": " + what);
}

}  // namespace lumavel::host
