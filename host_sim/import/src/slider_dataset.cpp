#include "lumavel/host/slider_dataset.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "lumavel/host/csv_table.hpp"
#include "lumavel/host/groundtruth.hpp"
#include "lumavel/host/path_check.hpp"
#include "lumavel/host/recording_error.hpp"

namespace lumavel::host {
namespace {

// Calls row(fields, line_no) for each non-empty, non-comment line.
template <typename Row>
void for_each_row(const std::string& path, Row row) {
  if (const std::string why = why_not_a_file(path); !why.empty()) throw recording_error_in(path, why);
  std::ifstream in(path);
  if (!in) throw recording_error_in(path, "cannot open");
  std::string line;
  std::vector<char> buf;
  long no = 0;
  // As a recording's tables are read: a line too long for a row (a binary or
  // damaged file) is refused before it is all in memory.
  while (next_table_line(in, buf, line, path, no + 1)) {
    ++no;
    if (no == 1 && line.rfind("\xEF\xBB\xBF", 0) == 0) line.erase(0, 3);  // UTF-8 byte order mark
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const size_t first = line.find_first_not_of(" \t");
    if (first == std::string::npos || line[first] == '#') continue;
    std::istringstream fields(line);
    row(fields, no);
  }
}

// The next whitespace-separated field, whole ("1.5abc" is not 1.5), read as
// the recording tables read theirs: decimal, finite.
double number(std::istringstream& s, const std::string& path, long line, const char* what) {
  std::string field;
  if (!(s >> field)) throw recording_error_at(path, line, std::string("missing ") + what);
  return parse_finite(field, path, line, what);
}

// Times become int64 nanoseconds in the recording written from them.
constexpr double kMaxTimeS = 9.2e9;

// A linear slider's track is a few metres at most: positions further apart
// than this are in another unit (millimetres: a 1 m track read as 1000 m was
// imported, exit 0, 'largest blended frame spacing 12.43 m', and run flagged
// NO_STEREO on nearly every frame).
constexpr double kMaxSliderTrackM = 10.0;

double time_s(std::istringstream& s, const std::string& path, long line) {
  const double t = number(s, path, line, "time");
  if (!(t >= 0 && t <= kMaxTimeS))
    throw recording_error_at(path, line,
                             "time " + format_double(t) + " s is outside 0..9.2e9 s (nanoseconds in a signed 64-bit "
                                                           "timestamp)");
  return t;
}

void no_more_fields(std::istringstream& s, const std::string& path, long line, const char* expected) {
  std::string extra;
  if (s >> extra)
    throw recording_error_at(path, line,
                             "unexpected extra field '" + shown_path(extra) + "' (expected " + expected + ")");
}

// Compared as the recording's nanoseconds: times less than 1 ns apart
// became one timestamp twice, refused by the writer naming the recording's
// table, not this file's line (was: 'OUT/mav0/cam0/data.csv: timestamp
// 10000000 is not after the previous one').
void check_increasing(double prev, long prev_line, double t, const std::string& path, long line) {
  if (prev_line == 0 || slider_time_ns(t) > slider_time_ns(prev)) return;
  throw recording_error_at(path, line,
                           "time " + format_double(t) + " s is not after line " + std::to_string(prev_line) + "'s, " +
                               format_double(prev) + " s" +
                               (t > prev ? ", to the nanosecond (the recording's timestamps are whole nanoseconds)" : ""));
}

}  // namespace

SliderDataset read_slider_dataset(const std::string& dir) {
  // (was: '/nonexistent/images.txt: does not exist', as if only the file were missing)
  if (const std::string why = why_not_a_folder(dir, kSliderDatasetFolder); !why.empty())
    throw recording_error_in(dir, why);
  SliderDataset d;
  const std::string images = dir + "/images.txt";
  FrameNames named;
  for_each_row(images, [&](std::istringstream& s, long line) {
    SliderFrame f;
    f.t = time_s(s, images, line);
    f.line = line;
    // The rest of the line is the name: it may hold spaces.
    std::string file;
    std::getline(s >> std::ws, file);
    while (!file.empty() && (file.back() == ' ' || file.back() == '\t')) file.pop_back();
    if (file.empty()) throw recording_error_at(images, line, "missing image file name");
    if (const std::string why = why_nul_in_name(file); !why.empty())
      throw recording_error_at(images, line, "image file name " + why);
    // (was: taken, exit 0; the repeated frame read as a standstill)
    f.path = file.front() == '/' ? file : dir + "/" + file;
    if (const std::string why = named.why_repeated(file, line, f.path); !why.empty())
      throw recording_error_at(images, line, why);
    check_increasing(d.frames.empty() ? 0 : d.frames.back().t, d.frames.empty() ? 0 : d.frames.back().line, f.t, images,
                     line);
    d.frames.push_back(f);
  });
  if (d.frames.size() < 2) throw recording_error_in(images, "fewer than two frames");

  const std::string gt = dir + "/groundtruth.txt";
  static const char* const kCols[] = {"x", "y", "z", "qx", "qy", "qz", "qw"};
  for_each_row(gt, [&](std::istringstream& s, long line) {
    SliderPose p;
    p.t = time_s(s, gt, line);
    p.line = line;
    for (int k = 0; k < 3; ++k) {
      p.p[k] = number(s, gt, line, kCols[k]);
      // The recording's bound (was: 1e300 m imported, a speed of 2.5e301 m/s written).
      if (const std::string why = why_implausible_position(p.p[k]); !why.empty())
        throw recording_error_at(gt, line, std::string(kCols[k]) + ": " + why);
    }
    for (int k = 0; k < 4; ++k) p.q[k] = number(s, gt, line, kCols[3 + k]);
    no_more_fields(s, gt, line, "t x y z qx qy qz qw");
    const double n = std::sqrt(p.q[0] * p.q[0] + p.q[1] * p.q[1] + p.q[2] * p.q[2] + p.q[3] * p.q[3]);
    if (const std::string why = why_not_unit_quaternion(n); !why.empty())
      throw recording_error_at(gt, line, "qx qy qz qw " + why);
    check_increasing(d.poses.empty() ? 0 : d.poses.back().t, d.poses.empty() ? 0 : d.poses.back().line, p.t, gt, line);
    for (int k = 0; k < 3 && !d.poses.empty(); ++k)
      if (std::fabs(p.p[k] - d.poses.front().p[k]) > kMaxSliderTrackM) {
        char why[320];
        std::snprintf(why, sizeof why,
                      "%s = %g m is %g m from line %ld's %g m: a linear slider's track is at most %g m (positions "
                      "in millimetres? they must be metres)",
                      kCols[k], p.p[k], std::fabs(p.p[k] - d.poses.front().p[k]), d.poses.front().line,
                      d.poses.front().p[k], kMaxSliderTrackM);
        throw recording_error_at(gt, line, why);
      }
    d.poses.push_back(p);
  });
  if (d.poses.size() < 2) throw recording_error_in(gt, "fewer than two ground-truth samples");

  const std::string calib = dir + "/calib.txt";
  int rows = 0;
  for_each_row(calib, [&](std::istringstream& s, long line) {
    if (rows++) throw recording_error_at(calib, line, "expected one line: fx fy cx cy k1 k2 p1 p2 k3");
    SliderCalib& c = d.calib;
    c.fx = number(s, calib, line, "fx");
    c.fy = number(s, calib, line, "fy");
    c.cx = number(s, calib, line, "cx");
    c.cy = number(s, calib, line, "cy");
    double* k[] = {&c.k1, &c.k2, &c.p1, &c.p2, &c.k3};
    static const char* const kNames[] = {"k1", "k2", "p1", "p2", "k3"};
    for (int i = 0; i < 5; ++i) *k[i] = number(s, calib, line, kNames[i]);
    no_more_fields(s, calib, line, "fx fy cx cy k1 k2 p1 p2 k3");
    // The values said, as sensor.yaml's intrinsics are (was: 'focal lengths
    // must be positive' alone, the value and which of the two unsaid).
    if (c.fx <= 0 || c.fy <= 0)
      throw recording_error_at(calib, line, "fx = " + format_double(c.fx) + ", fy = " + format_double(c.fy) +
                                                ": the focal lengths fx and fy must be positive");
  });
  if (!rows) throw recording_error_in(calib, "empty (expected fx fy cx cy k1 k2 p1 p2 k3)");
  return d;
}

}  // namespace lumavel::host
