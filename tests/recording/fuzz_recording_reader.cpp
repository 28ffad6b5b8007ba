// libFuzzer target for the recording reader (issue 15): the first byte picks
// the reader, the rest is the file: a PNG or PGM frame, a gyro data.csv, a
// camera or an imu sensor.yaml. Each either reads or throws RecordingError
// (a std::runtime_error naming the file); any other exception, a crash or a
// sanitizer report is a finding. A value read must be what the file says:
// finite numbers only, images no larger than their own size.
#include <unistd.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "lumavel/host/csv_table.hpp"
#include "lumavel/host/image_io.hpp"
#include "lumavel/host/recording_error.hpp"
#include "lumavel/host/recording_layout.hpp"
#include "lumavel/host/sensor_yaml.hpp"

using namespace lumavel::host;

namespace {

void require(bool ok) {
  if (!ok) std::abort();
}

// The readers take paths: the input goes to one per-process file.
std::string as_file(const uint8_t* data, size_t len) {
  static const std::string path = "/tmp/lumavel_fuzz_recording_" + std::to_string(::getpid());
  std::FILE* f = std::fopen(path.c_str(), "wb");
  require(f != nullptr);
  if (len > 0) require(std::fwrite(data, 1, len, f) == len);
  std::fclose(f);
  return path;
}

void one(uint8_t kind, const uint8_t* data, size_t len) {
  switch (kind % 4) {
    case 0: {
      const GrayImage img = decode_gray_image(data, len, "frame");
      require(img.width > 0 && img.height > 0);
      require(img.px.size() == static_cast<size_t>(img.width) * static_cast<size_t>(img.height));
      break;
    }
    case 1: {
      const std::string path = as_file(data, len);
      for (const CsvRow& r : read_csv_table(path, layout::imu_columns()))
        for (size_t k = 0; k < r.fields.size(); ++k)
          require(std::isfinite(parse_finite(r.fields[k], path, r.line, layout::imu_columns()[k])));
      break;
    }
    case 2: {
      const CameraSensor c = read_camera_yaml(as_file(data, len));
      require(std::isfinite(c.fu) && std::isfinite(c.cu) && c.width > 0 && c.height > 0);
      break;
    }
    default: read_imu_yaml(as_file(data, len)); break;
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t len) {
  if (len == 0) return 0;
  try {
    one(data[0], data + 1, len - 1);
  } catch (const RecordingError&) {
    // refused, naming the file: the expected outcome for bad input
  }
  return 0;
}
