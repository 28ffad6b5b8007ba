// Compares two estimates CSVs at the report's resolution: every row's
// timestamp, V, distance, heading, status and gyro offset must be equal after
// quantisation to the report's fixed-point formats. Exit 0 if equal, 1 with
// the first difference otherwise.
#include <cinttypes>
#include <cstdio>
#include <exception>

#include "estimates_csv.hpp"

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: hid_csv_compare EXPECTED.csv ACTUAL.csv\n");
    return 2;
  }
  try {
    const auto a = lumavel::test::read_estimates_csv(argv[1]);
    const auto b = lumavel::test::read_estimates_csv(argv[2]);
    if (a.size() != b.size()) {
      std::fprintf(stderr, "hid_csv_compare: %s has %zu rows, %s has %zu\n", argv[1], a.size(), argv[2], b.size());
      return 1;
    }
    for (size_t i = 0; i < a.size(); ++i) {
      const auto& x = a[i];
      const auto& y = b[i];
      if (x.t_ns != y.t_ns || x.v != y.v || x.distance != y.distance || x.heading != y.heading ||
          x.status != y.status || x.gyro_offset != y.gyro_offset) {
        std::fprintf(stderr,
                     "hid_csv_compare: line %zu differs: expected t=%" PRIu64 " v=%d s=%" PRId64
                     " heading=%d status=%u gyro_offset=%d, got t=%" PRIu64 " v=%d s=%" PRId64
                     " heading=%d status=%u gyro_offset=%d\n",
                     i + 2, x.t_ns, x.v, x.distance, x.heading, unsigned{x.status}, x.gyro_offset, y.t_ns, y.v,
                     y.distance, y.heading, unsigned{y.status}, y.gyro_offset);
        return 1;
      }
    }
    std::printf("hid_csv_compare: %zu rows equal\n", a.size());
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "hid_csv_compare: %s\n", e.what());
    return 2;
  }
}
