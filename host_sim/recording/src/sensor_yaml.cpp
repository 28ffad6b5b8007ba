#include "lumavel/host/sensor_yaml.hpp"

#include <yaml-cpp/depthguard.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>

#include "lumavel/host/csv_table.hpp"
#include "lumavel/host/decimal_text.hpp"
#include "lumavel/host/image_io.hpp"
#include "lumavel/host/output_file.hpp"
#include "lumavel/host/path_check.hpp"
#include "lumavel/host/recording_error.hpp"
#include "lumavel/host/yaml_text.hpp"

namespace lumavel::host {
namespace {

long line_of(const YAML::Node& n) { return n.Mark().line + 1; }  // yaml-cpp lines are 0-based

// A derived upper bound for the message refusing `refused` (10 / 60 Hz as
// 0.1667, not 0.16666666666666666), with as many more digits as it takes to
// lie below the value refused: 'exposure_s = 0.1667 must be 0..0.1667 s' was
// a refusal its own words allow (now 0..0.16667 s).
std::string bound_below(double bound, double refused) {
  char b[32];
  for (int digits = 4; digits <= 17; ++digits) {
    std::snprintf(b, sizeof b, "%.*g", digits, bound);
    if (std::strtod(b, nullptr) < refused) break;
  }
  return b;
}

// The line of `key` itself (a block value such as T_BS's starts on the next line).
long key_line(const YAML::Node& root, const char* key) {
  for (const auto& kv : root)
    if (kv.first.IsScalar() && kv.first.Scalar() == key) return line_of(kv.first);
  return 0;
}

// yaml-cpp keeps every copy of a repeated key and answers with the first: a
// T_BS appended to correct a file would be ignored. One value per key, in
// the file's mapping and in the mappings it holds (T_BS).
void check_unique_keys(const YAML::Node& map, const std::string& path, const std::string& within, int depth = 0) {
  std::map<std::string, long> seen;
  for (const auto& kv : map) {
    if (!kv.first.IsScalar()) continue;
    const std::string key = within + kv.first.Scalar();
    const auto [at, fresh] = seen.emplace(key, line_of(kv.first));
    if (!fresh)
      throw recording_error_at(path, line_of(kv.first),
                               "key '" + shown_path(key) + "' is given again (first at line " + std::to_string(at->second) +
                                   "): one value per key");
    if (depth == 0 && kv.second.IsMap()) check_unique_keys(kv.second, path, key + ".", depth + 1);
  }
}

YAML::Node load_yaml(const std::string& path) {
  if (const std::string why = why_not_a_file(path); !why.empty()) throw recording_error_in(path, why);
  if (const std::string why = why_too_big_for_text(path, "a sensor.yaml holds a few keys"); !why.empty())
    throw recording_error_in(path, why);
  std::ifstream in(path);
  if (!in) throw recording_error_in(path, std::string("cannot open: ") + std::strerror(errno));
  std::stringstream ss;
  ss << in.rdbuf();
  std::string text = ss.str();
  // OpenCV-style "%YAML:1.0" first lines are not YAML 1.2 directives; blank
  // them (keeping line numbers) so such files still load.
  if (text.rfind("%YAML:", 0) == 0) text[0] = '#';
  if (const yaml_text::BadLine bad = yaml_text::why_bad_line(text); bad.line != 0)
    throw recording_error_at(path, bad.line, bad.why);
  try {
    // A second document (a '---' line after some content) would be ignored,
    // silently: refused like a repeated key. (Scanned in the text: yaml-cpp's
    // LoadAll can loop on malformed input.)
    // So would the text after a '...' end marker (was: exit 0, the keys
    // after it ignored).
    if (const yaml_text::NotOneDocument bad = yaml_text::why_not_one_document(text); bad.line != 0)
      throw recording_error_at(path, bad.line, bad.why + ": a sensor.yaml is one mapping of keys");
    YAML::Node root = YAML::Load(text);
    if (root.IsNull())
      throw recording_error_in(path, yaml_text::why_null_document(text) +
                                         ": a sensor.yaml holds the sensor's keys (docs/recording-format.md)");
    if (!root.IsMap())
      throw recording_error_at(path, line_of(root),
                               "not a YAML mapping of sensor keys (KEY: VALUE lines, docs/recording-format.md)");
    check_unique_keys(root, path, "");
    return root;
  } catch (const YAML::DeepRecursion& e) {
    // yaml-cpp's own words for it are "bad file" (was: 'YAML syntax error:
    // bad file', no rule said).
    throw recording_error_at(path, e.mark.line + 1,
                             "YAML nested " + std::to_string(e.depth()) +
                                 " levels deep, as deep as the YAML reader goes: a sensor.yaml is one mapping of keys "
                                 "whose values are numbers, lists of numbers and T_BS's matrix");
  } catch (const YAML::ParserException& e) {
    throw recording_error_at(path, e.mark.line + 1,
                             "YAML syntax error: " + e.msg + yaml_text::tab_indent_note(text, e.mark.line + 1));
  }
}

// A key with nothing after it holds a null node placed at the next token,
// lines further on: 'rate_hz:' said 'sensor.yaml:16: rate_hz: expected a
// number', 16 the line of the key after it. Refused at the key's own line.
void refuse_empty_value(const YAML::Node& map, const char* key, const std::string& shown_key, const std::string& path) {
  if (map[key].IsNull())
    throw recording_error_at(path, key_line(map, key), shown_key + ": no value after the key (empty, or null)");
}

// `parent`: the mapping's own key, for keys inside one (T_BS.data).
YAML::Node require(const YAML::Node& root, const char* key, const std::string& path, const char* parent = nullptr) {
  YAML::Node n = root[key];
  if (!n) {
    const std::string what = std::string("missing key '") + (parent ? std::string(parent) + "." : "") + key + "'";
    throw parent == nullptr || root.Mark().is_null() ? recording_error_in(path, what)
                                                     : recording_error_at(path, line_of(root), what);
  }
  refuse_empty_value(root, key, parent ? std::string(parent) + "." + key : std::string(key), path);
  return n;
}

double number(const YAML::Node& n, const std::string& what, const std::string& path) {
  double v = 0;
  try {
    if (!n.IsScalar()) throw YAML::Exception(n.Mark(), "");
    v = n.as<double>();
  } catch (const YAML::Exception&) {
    // A number too large for a double is a number: said as the tables say
    // it (was: 'rate_hz: expected a number, got '1e400'').
    if (n.IsScalar() && read_decimal(n.Scalar()).problem == DecimalText::Problem::kOverflow)
      throw recording_error_at(path, line_of(n), what + ": value '" + shown_path(n.Scalar()) +
                                                     "' is beyond the largest number (about 1.8e308)");
    throw recording_error_at(path, line_of(n), what + ": expected a number" +
                                                   (n.IsScalar() ? ", got '" + shown_path(n.Scalar()) + "'" : std::string()));
  }
  if (!std::isfinite(v))
    throw recording_error_at(path, line_of(n), what + ": value is not finite, got '" + shown_path(n.Scalar()) + "'");
  // A number too small for a double is read as 0 (or a subnormal): said as
  // such (was: 'rate_hz: 1e-400' said 'rate_hz = 0 must be positive', a
  // value the file does not hold).
  if (read_decimal(n.Scalar()).underflow)
    throw recording_error_at(path, line_of(n), what + ": value '" + shown_path(n.Scalar()) +
                                                   "' is " + kNearerZeroThanAnyNumber);
  return v;
}

std::vector<double> numbers(const YAML::Node& n, const std::string& what, size_t count, const std::string& path) {
  if (!n.IsSequence()) throw recording_error_at(path, line_of(n), what + ": expected a list of numbers");
  if (count != 0 && n.size() != count)
    throw recording_error_at(path, line_of(n),
                             what + ": expected " + std::to_string(count) + " numbers, found " +
                                 std::to_string(n.size()));
  std::vector<double> out;
  for (size_t i = 0; i < n.size(); ++i) out.push_back(number(n[i], what + "[" + std::to_string(i) + "]", path));
  return out;
}

std::string text_of(const YAML::Node& n, const std::string& what, const std::string& path) {
  if (!n.IsScalar()) throw recording_error_at(path, line_of(n), what + ": expected text");
  return n.Scalar();
}

void check_sensor_type(const YAML::Node& root, const char* want, const std::string& path) {
  const YAML::Node n = require(root, "sensor_type", path);
  const std::string got = text_of(n, "sensor_type", path);
  if (got != want)
    throw recording_error_at(path, line_of(n), "sensor_type is '" + shown_path(got) + "', expected '" + want + "'");
}

Pose read_pose(const YAML::Node& root, const std::string& path) {
  const YAML::Node t = require(root, "T_BS", path);
  if (!t.IsMap()) throw recording_error_at(path, line_of(t), "T_BS: expected {cols: 4, rows: 4, data: [16 numbers]}");
  const double cols = number(require(t, "cols", path, "T_BS"), "T_BS.cols", path);
  const double rows = number(require(t, "rows", path, "T_BS"), "T_BS.rows", path);
  if (cols != 4.0 || rows != 4.0)
    throw recording_error_at(path, line_of(t), "T_BS is " + format_double(rows) + "x" + format_double(cols) +
                                                   " (rows x cols): it must be 4x4");
  const std::vector<double> d = numbers(require(t, "data", path, "T_BS"), "T_BS.data", 16, path);
  // A pose: orthonormal rotation, last row 0 0 0 1. Loose tolerance: files
  // carry calibrations printed to a few digits.
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      double dot = 0;
      for (int k = 0; k < 3; ++k) dot += d[static_cast<size_t>(4 * k + i)] * d[static_cast<size_t>(4 * k + j)];
      // A column against itself is its squared length (was said as 'columns
      // 0 and 0 have dot product 4, not 1').
      if (std::fabs(dot - (i == j ? 1.0 : 0.0)) > 1e-3)
        throw recording_error_at(path, line_of(t),
                                 "T_BS: rotation part is not orthonormal: " +
                                     (i == j ? "column " + std::to_string(i) + " has squared length " +
                                                   format_double(dot) + ", not 1"
                                             : "columns " + std::to_string(i) + " and " + std::to_string(j) +
                                                   " have dot product " + format_double(dot) + ", not 0") +
                                     " (within 0.001)");
    }
  // Orthonormal with determinant -1 is a mirror: it flips the image's u
  // axis against the body's and gives an answer that is wrong, not refused.
  const double det = d[0] * (d[5] * d[10] - d[6] * d[9]) - d[1] * (d[4] * d[10] - d[6] * d[8]) +
                     d[2] * (d[4] * d[9] - d[5] * d[8]);
  if (det < 0) {
    char b[32];
    std::snprintf(b, sizeof b, "%.4g", det);
    throw recording_error_at(path, line_of(t), std::string("T_BS: rotation part has determinant ") + b +
                                                   ": a reflection, not a rotation (check the sign of one axis)");
  }
  if (std::fabs(d[12]) + std::fabs(d[13]) + std::fabs(d[14]) > 1e-9 || std::fabs(d[15] - 1.0) > 1e-9)
    throw recording_error_at(path, line_of(t), "T_BS: last row is " + format_double(d[12]) + ", " +
                                                   format_double(d[13]) + ", " + format_double(d[14]) + ", " +
                                                   format_double(d[15]) + ": it must be 0, 0, 0, 1");
  if (std::fabs(d[3]) > kMaxSensorOffsetM || std::fabs(d[7]) > kMaxSensorOffsetM || std::fabs(d[11]) > kMaxSensorOffsetM)
    throw recording_error_at(path, line_of(t), "T_BS: translation (" + format_double(d[3]) + ", " + format_double(d[7]) +
                                                   ", " + format_double(d[11]) + ") m: each component must be within +-" +
                                                   format_double(kMaxSensorOffsetM) +
                                                   " m (a sensor on the vehicle, near the body origin)");
  Pose p;
  for (size_t i = 0; i < 16; ++i) p[i] = d[i];
  return p;
}

// -1 when absent (the optional physical quantities are never negative: a
// negative value in the file is an error, not a way to say "absent"). At
// most `hi`, `range` saying the range and its unit ("0..10 rad/s/sqrt(Hz)")
// for the value it refuses.
double optional_number(const YAML::Node& root, const char* key, const std::string& path, double hi,
                       const std::function<std::string(double)>& range) {
  const YAML::Node n = root[key];
  if (!n) return -1.0;
  refuse_empty_value(root, key, key, path);
  const double v = number(n, key, path);
  if (v < 0)
    throw recording_error_at(path, line_of(n), std::string(key) + " = " + format_double(v) + " must not be negative");
  if (v > hi)
    throw recording_error_at(path, line_of(n), std::string(key) + " = " + format_double(v) + " must be " + range(v));
  return v;
}

// rate_hz, positive and at most kMaxRateHz; its line in `line`.
double read_rate(const YAML::Node& root, const std::string& path, long& line) {
  const double rate = number(require(root, "rate_hz", path), "rate_hz", path);
  line = line_of(root["rate_hz"]);
  if (rate <= 0) throw recording_error_at(path, line, "rate_hz = " + format_double(rate) + " must be positive");
  if (rate > kMaxRateHz)
    throw recording_error_at(path, line, "rate_hz = " + format_double(rate) + " must be at most " +
                                             format_double(kMaxRateHz) + " Hz (a period of 1 us or more)");
  return rate;
}

std::string optional_text(const YAML::Node& root, const char* key) {
  const YAML::Node n = root[key];
  return (n && n.IsScalar()) ? n.Scalar() : std::string();
}

// Comments go out double-quoted: drop what would end the string or the line.
std::string quoted(const std::string& text) {
  std::string out = "\"";
  for (char ch : text)
    if (ch != '"' && ch != '\\' && ch != '\n' && ch != '\r') out += ch;
  return out + "\"";
}

std::string list(const std::vector<double>& v) {
  std::string s = "[";
  for (size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + format_double(v[i]);
  return s + "]";
}

std::string pose_text(const Pose& p) {
  std::string s = "T_BS:\n  cols: 4\n  rows: 4\n  data: [";
  for (size_t i = 0; i < 16; ++i) {
    s += format_double(p[i]);
    if (i == 15) break;
    s += (i % 4 == 3) ? ",\n         " : ", ";
  }
  return s + "]\n";
}

void write_text(const std::string& path, const std::string& text) { write_file(path, text, "the sensor.yaml"); }

}  // namespace

void check_intrinsics(const CameraSensor& c, const std::string& file, long line) {
  auto range = [](int size) { return "] = [" + std::to_string(-size) + ", " + std::to_string(2 * size) + "] px"; };
  if (!(c.cu >= -c.width && c.cu <= 2.0 * c.width))
    throw recording_error_at(file, line, "intrinsics: principal point cu = " + format_double(c.cu) +
                                             " px must lie in [-width, 2 width" + range(c.width));
  if (!(c.fv >= 0.5 * c.fu && c.fv <= 2 * c.fu))
    throw recording_error_at(file, line, "intrinsics: fu = " + format_double(c.fu) + " px, fv = " + format_double(c.fv) +
                                             " px: fv/fu must be 0.5..2 (pixels at most 2:1 out of square)");
  if (!(c.cv >= -c.height && c.cv <= 2.0 * c.height))
    throw recording_error_at(file, line, "intrinsics: principal point cv = " + format_double(c.cv) +
                                             " px must lie in [-height, 2 height" + range(c.height));
}

Pose identity_pose() { return {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}; }

CameraSensor read_camera_yaml(const std::string& path) {
  const YAML::Node root = load_yaml(path);
  check_sensor_type(root, "camera", path);
  CameraSensor c;
  c.rate_hz = read_rate(root, path, c.line.rate_hz);
  const YAML::Node res = require(root, "resolution", path);
  const std::vector<double> r = numbers(res, "resolution", 2, path);
  if (r[0] < 1 || r[1] < 1 || r[0] > kMaxImageSide || r[1] > kMaxImageSide || r[0] != std::floor(r[0]) ||
      r[1] != std::floor(r[1]))
    throw recording_error_at(path, line_of(res), "resolution: [" + format_double(r[0]) + ", " + format_double(r[1]) +
                                                     "]: expected [width, height] in whole pixels, 1.." +
                                                     std::to_string(kMaxImageSide));
  // (was: refused at frame 0, "cannot bin to the working resolution", no rule said)
  if (const std::string why = why_too_many_pixels(r[0], r[1]); !why.empty())
    throw recording_error_at(path, line_of(res),
                             "resolution: [" + format_double(r[0]) + ", " + format_double(r[1]) + "] " + why);
  c.line.resolution = line_of(res);
  c.width = static_cast<int>(r[0]);
  c.height = static_cast<int>(r[1]);
  const YAML::Node model = require(root, "camera_model", path);
  if (text_of(model, "camera_model", path) != "pinhole")
    throw recording_error_at(path, line_of(model), "camera_model '" + shown_path(model.Scalar()) + "' is not supported (pinhole)");
  const YAML::Node in = require(root, "intrinsics", path);
  const std::vector<double> k = numbers(in, "intrinsics", 4, path);
  c.line.intrinsics = line_of(in);
  c.fu = k[0];
  c.fv = k[1];
  c.cu = k[2];
  c.cv = k[3];
  if (c.fu <= 0 || c.fv <= 0)
    throw recording_error_at(path, line_of(in), "intrinsics: fu = " + format_double(c.fu) + ", fv = " + format_double(c.fv) +
                                                    ": fu and fv must be positive");
  check_intrinsics(c, path, line_of(in));
  const YAML::Node dm = require(root, "distortion_model", path);
  c.distortion_model = text_of(dm, "distortion_model", path);
  if (c.distortion_model != "radial-tangential")
    throw recording_error_at(path, line_of(dm),
                             "distortion_model '" + shown_path(c.distortion_model) + "' is not supported (radial-tangential)");
  const YAML::Node dc = require(root, "distortion_coefficients", path);
  c.distortion = numbers(dc, "distortion_coefficients", 4, path);
  c.line.distortion = line_of(dc);
  c.T_BS = read_pose(root, path);
  c.line.T_BS = key_line(root, "T_BS");
  const double longest = kMaxExposureFrames / c.rate_hz;
  c.exposure_s = optional_number(root, "exposure_s", path, longest, [&](double refused) {
    return "0.." + bound_below(longest, refused) + " s (at most " + format_double(kMaxExposureFrames) +
           " frame periods, " + format_double(kMaxExposureFrames) + " / rate_hz)";
  });
  c.comment = optional_text(root, "comment");
  return c;
}

ImuSensor read_imu_yaml(const std::string& path) {
  const YAML::Node root = load_yaml(path);
  check_sensor_type(root, "imu", path);
  ImuSensor s;
  s.rate_hz = read_rate(root, path, s.line.rate_hz);
  s.T_BS = read_pose(root, path);
  s.gyroscope_noise_density = optional_number(root, "gyroscope_noise_density", path, kMaxGyroNoiseDensity, [](double) {
    return "0.." + format_double(kMaxGyroNoiseDensity) + " rad/s/sqrt(Hz)";
  });
  s.gyroscope_random_walk = optional_number(root, "gyroscope_random_walk", path, kMaxGyroRandomWalk, [](double) {
    return "0.." + format_double(kMaxGyroRandomWalk) + " rad/s^2/sqrt(Hz)";
  });
  s.comment = optional_text(root, "comment");
  return s;
}

void write_camera_yaml(const std::string& path, const CameraSensor& c) {
  std::string s = "# General sensor definitions.\nsensor_type: camera\n";
  if (!c.comment.empty()) s += "comment: " + quoted(c.comment) + "\n";
  s += "\n# Sensor extrinsics wrt. the body-frame.\n" + pose_text(c.T_BS);
  s += "\n# Camera specific definitions.\n";
  s += "rate_hz: " + format_double(c.rate_hz) + "\n";
  s += "resolution: [" + std::to_string(c.width) + ", " + std::to_string(c.height) + "]\n";
  s += "camera_model: pinhole\n";
  s += "intrinsics: " + list({c.fu, c.fv, c.cu, c.cv}) + " #fu, fv, cu, cv\n";
  s += "distortion_model: " + c.distortion_model + "\n";
  std::vector<double> d = c.distortion;
  d.resize(4, 0.0);
  s += "distortion_coefficients: " + list(d) + "\n";
  if (c.exposure_s >= 0) s += "exposure_s: " + format_double(c.exposure_s) + "\n";
  write_text(path, s);
}

void write_imu_yaml(const std::string& path, const ImuSensor& imu) {
  std::string s = "# General sensor definitions.\nsensor_type: imu\n";
  if (!imu.comment.empty()) s += "comment: " + quoted(imu.comment) + "\n";
  s += "\n# Sensor extrinsics wrt. the body-frame.\n" + pose_text(imu.T_BS);
  s += "rate_hz: " + format_double(imu.rate_hz) + "\n";
  if (imu.gyroscope_noise_density >= 0)
    s += "\n# inertial sensor noise model parameters (static)\ngyroscope_noise_density: " +
         format_double(imu.gyroscope_noise_density) + "     # [ rad / s / sqrt(Hz) ]\n";
  if (imu.gyroscope_random_walk >= 0)
    s += "gyroscope_random_walk: " + format_double(imu.gyroscope_random_walk) + "       # [ rad / s^2 / sqrt(Hz) ]\n";
  write_text(path, s);
}

}  // namespace lumavel::host
