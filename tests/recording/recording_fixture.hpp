// Tiny recordings generated inside the tests (nothing binary is committed):
// a textured wall moving past a left-looking stereo rig, a gyro, ground truth,
// plus helpers to damage the files line by line.
#pragma once
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "lumavel/host/recording_writer.hpp"

namespace fixture {

using namespace lumavel::host;

class TempDir {
 public:
  TempDir() {
    char tmpl[] = "/tmp/lumavel_test_XXXXXX";
    path_ = ::mkdtemp(tmpl) ? tmpl : "";
  }
  ~TempDir() {
    std::error_code ec;
    if (!path_.empty()) std::filesystem::remove_all(path_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

// Left-looking upright camera (optical axis +y, image u along body +x) at
// body x = `x`.
inline CameraSensor left_camera(int w, int h, double x) {
  CameraSensor c;
  c.rate_hz = 100;
  c.width = w;
  c.height = h;
  c.fu = c.fv = 0.9 * w;
  c.cu = 0.5 * w - 0.5;
  c.cv = 0.5 * h - 0.5;
  c.distortion = {0.01, -0.002, 0.0003, -0.0004};
  c.T_BS = {1, 0, 0, x, 0, 0, 1, 0, 0, -1, 0, 0, 0, 0, 0, 1};
  return c;
}

struct Options {
  int width = 40, height = 30;
  int frames = 12;
  uint64_t t0 = 1000000000ull;
  uint64_t frame_dt = 10000000ull;  // 100 Hz
  uint64_t gyro_dt = 2000000ull;    // 500 Hz
  double yaw_rate = 0.02;           // rad/s about body z
  double speed = 1.0;               // m/s along body x
  bool groundtruth = true;
  ImageFormat format = ImageFormat::kPng;
  std::vector<int> drop_frames;     // frame indices left out (gaps)
  uint64_t gyro_hole_from = 0, gyro_hole_to = 0;  // samples in [from, to) left out
};

inline uint8_t pixel(int frame, int cam, int u, int v) {
  const double x = u + 0.37 * frame + 1.5 * cam;
  return static_cast<uint8_t>(std::lround(120 + 60 * std::sin(0.7 * x) + 30 * std::sin(1.9 * x + 0.5) + v % 3));
}

inline std::vector<uint8_t> frame_pixels(const Options& o, int frame, int cam) {
  std::vector<uint8_t> px(static_cast<size_t>(o.width) * static_cast<size_t>(o.height));
  for (int v = 0; v < o.height; ++v)
    for (int u = 0; u < o.width; ++u) px[static_cast<size_t>(v * o.width + u)] = pixel(frame, cam, u, v);
  return px;
}

inline uint64_t frame_time(const Options& o, int frame) { return o.t0 + static_cast<uint64_t>(frame) * o.frame_dt; }

// Writes REC (= dir) with REC/mav0/...; returns REC.
inline std::string write_recording(const std::string& dir, const Options& o = {}) {
  ImuSensor imu;
  imu.rate_hz = 1e9 / static_cast<double>(o.gyro_dt);
  imu.gyroscope_noise_density = 1.7e-4;
  RecordingWriter w(dir, left_camera(o.width, o.height, -0.04), left_camera(o.width, o.height, 0.04), imu, o.format);
  for (int i = 0; i < o.frames; ++i) {
    bool dropped = false;
    for (int d : o.drop_frames) dropped = dropped || d == i;
    if (dropped) continue;
    const std::vector<uint8_t> a = frame_pixels(o, i, 0), b = frame_pixels(o, i, 1);
    w.add_frame_pair(frame_time(o, i), a.data(), b.data());
  }
  const uint64_t end = frame_time(o, o.frames);
  for (uint64_t t = o.t0 - o.frame_dt; t <= end; t += o.gyro_dt) {
    if (t >= o.gyro_hole_from && t < o.gyro_hole_to) continue;
    const double wv[3] = {0.001, -0.002, o.yaw_rate}, a[3] = {0.1, 0, 9.81};
    w.add_imu(t, wv, a);
  }
  if (o.groundtruth) {
    for (uint64_t t = o.t0 - o.frame_dt; t <= end; t += 5000000ull) {
      GroundTruthSample g;
      g.t_ns = t;
      // Signed: the rows before the first frame (t < t0) are at negative times
      // (an unsigned t - t0 wrapped to 1.8e10 s, 1.8e10 m away).
      const double since_t0_s = (static_cast<double>(t) - static_cast<double>(o.t0)) * 1e-9;
      const double yaw = o.yaw_rate * since_t0_s;
      g.q[0] = std::cos(yaw / 2);
      g.q[3] = std::sin(yaw / 2);
      g.v[0] = o.speed * std::cos(yaw);
      g.v[1] = o.speed * std::sin(yaw);
      g.p[0] = o.speed * since_t0_s;
      w.add_groundtruth(g);
    }
  }
  w.finish();
  return dir;
}

inline std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

inline void write_text(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << text;
}

inline std::vector<std::string> read_lines(const std::string& path) {
  std::vector<std::string> lines;
  std::ifstream in(path);
  std::string l;
  while (std::getline(in, l)) lines.push_back(l);
  return lines;
}

inline void write_lines(const std::string& path, const std::vector<std::string>& lines) {
  std::string t;
  for (const std::string& l : lines) t += l + "\n";
  write_text(path, t);
}

// Replaces 1-based line `line` of a text file.
inline void set_line(const std::string& path, size_t line, const std::string& text) {
  std::vector<std::string> lines = read_lines(path);
  lines.at(line - 1) = text;
  write_lines(path, lines);
}

inline void erase_line(const std::string& path, size_t line) {
  std::vector<std::string> lines = read_lines(path);
  lines.erase(lines.begin() + static_cast<long>(line - 1));
  write_lines(path, lines);
}

// Replaces the first `from` in a file by `to`.
inline void replace_in(const std::string& path, const std::string& from, const std::string& to) {
  std::string t = read_text(path);
  const size_t at = t.find(from);
  if (at == std::string::npos) throw std::logic_error(path + ": no '" + from + "' to replace");
  t.replace(at, from.size(), to);
  write_text(path, t);
}

// Field `col` (0-based, timestamp 0) of 1-based line `line` of a CSV.
inline void set_field(const std::string& path, size_t line, size_t col, const std::string& value) {
  std::vector<std::string> lines = read_lines(path);
  std::string& l = lines.at(line - 1);
  size_t start = 0;
  for (size_t c = 0; c < col; ++c) start = l.find(',', start) + 1;
  const size_t end = l.find(',', start);
  l.replace(start, (end == std::string::npos ? l.size() : end) - start, value);
  write_lines(path, lines);
}

// The message of the RecordingError thrown by f, or "(no error)".
inline std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const RecordingError& e) {
    return e.what();
  } catch (const std::exception& e) {
    return std::string("(wrong exception type) ") + e.what();
  }
  return "(no error)";
}

// Loads and decodes one recording before any test runs: yaml-cpp and the C++
// runtime allocate function-local statics on first use, which CppUTest's leak
// check would otherwise blame on whichever test happens to run first.
inline bool warm_up_statics() {
  TempDir d;
  const Recording r = load_recording(write_recording(d.path() + "/warm"));
  (void)error_of([] { read_camera_yaml("/nonexistent/sensor.yaml"); });
  (void)r;
  return true;
}
inline const bool kStaticsWarm = warm_up_statics();

}  // namespace fixture
