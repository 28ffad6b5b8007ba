// Writes a synthetic estimates CSV in the `lumavel-sim run` layout: a drive
// with speed changes, reversing, a heading that wraps through +-pi, every
// status bit, values at the report's fixed-point resolution (shortest decimals).
#include <charconv>
#include <cstdint>
#include <initializer_list>
#include <cmath>
#include <cstdio>
#include <cstdlib>

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: make_test_estimates ROWS OUT.csv\n");
    return 2;
  }
  const long rows = std::strtol(argv[1], nullptr, 10);
  std::FILE* f = std::fopen(argv[2], "w");
  if (f == nullptr || rows <= 0) {
    std::fprintf(stderr, "make_test_estimates: cannot write %s\n", argv[2]);
    return 1;
  }
  std::fprintf(f, "timestamp_ns,v_xb_mps,distance_m,heading_rad,status,gyro_offset_radps\n");
  const double pi = 3.14159265358979323846;
  int64_t dist_q32 = 0;
  for (long i = 0; i < rows; ++i) {
    const uint64_t t = 1700000000000000000ull + static_cast<uint64_t>(i) * 16666667ull;
    const double v = 2.5 * std::sin(static_cast<double>(i) / 23.0) + 0.7;  // reverses at times
    const int32_t v_q16 = static_cast<int32_t>(std::lround(v * 65536.0));
    dist_q32 += static_cast<int64_t>(v_q16) * 65536 / 60;
    double h = 3.0 + 0.013 * static_cast<double>(i);
    h = std::fmod(h + pi, 2 * pi) - pi;
    int32_t h_q28 = static_cast<int32_t>(std::lround(h * 268435456.0));
    if (h_q28 > 843314856) h_q28 = 843314856;  // stay inside [-pi, pi) after rounding
    const unsigned status = (i % 9 == 0) ? (1u << (i / 9 % 8)) : 0u;  // every bit, STILL (7) too
    // A learned offset that steps now and then, either sign (RateQ24 values).
    const int32_t offset_q24 = static_cast<int32_t>((i / 40) % 5 - 2) * 8389;
    // Shortest round-trip decimals of the exact fixed-point values, as lumavel-sim writes them.
    char line[160];
    char* const end = line + sizeof line;
    char* p = std::to_chars(line, end, t).ptr;
    for (const double x : {v_q16 / 65536.0, static_cast<double>(dist_q32) / 4294967296.0, h_q28 / 268435456.0}) {
      *p++ = ',';
      p = std::to_chars(p, end, x, std::chars_format::general).ptr;
    }
    *p++ = ',';
    p = std::to_chars(p, end, status).ptr;
    *p++ = ',';
    p = std::to_chars(p, end, std::ldexp(offset_q24, -24), std::chars_format::general).ptr;
    *p++ = '\n';
    std::fwrite(line, 1, static_cast<size_t>(p - line), f);
  }
  return std::fclose(f) == 0 ? 0 : 1;
}
