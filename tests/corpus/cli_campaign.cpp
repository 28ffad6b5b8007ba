// The corrupted-input campaign of the command-line tools: damaged copies of a
// recording (the fixture's, or --base REC, e.g. a copy of out/reproduce/rec/
// wall_40x30), of a slider dataset, of configuration and report files, each
// run through the real executables from another folder with a timeout, and
// each outcome classified:
//   crash    a signal or a sanitizer report
//   hang     still running at the timeout
//   silent   exit 0 on bad input with no status flag raised
//   unclear  refused, but the message does not name the file and the line,
//            frame or value
//   wrong    a harmless variation (CRLF, BOM, blank lines) changed the answer
// Prints one line per case and exits 1 when any fails. CTest runs it on the
// fixture (corpus_cli_campaign); by hand:
//   build/tests/corpus/cli_campaign --sim build/host_sim/sim/lumavel-sim
//     --read build/tools/lumavel-read/lumavel-read --base /tmp/wall_40x30 --keep /tmp/campaign
#include <png.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <functional>
#include <string>
#include <thread>
#include <tuple>
#include <vector>

#if LUMAVEL_CAMPAIGN_JPEG
#include <jpeglib.h>
#endif

#include "lumavel/host/image_io.hpp"
#include "lumavel/protocol/reports.hpp"
#include "recording_fixture.hpp"

namespace fs = std::filesystem;
using fixture::read_lines;
using fixture::read_text;
using fixture::replace_in;
using fixture::set_field;
using fixture::write_lines;
using fixture::write_text;

namespace {

// ---- what a case is ----------------------------------------------------------

enum class Expect {
  kRefused,   // non-zero exit, the message names `file` and `where`
  kFlagged,   // exit 0 with a status flag raised, or refused as above
  kSame,      // exit 0 and the very estimates of the intact input
};

struct Case {
  std::string name;
  std::string tool;  // run, calibrate, import, config, replay
  std::function<void(const std::string& dir)> damage;  // dir: the copy (REC, the dataset, the file's folder)
  Expect expect;
  std::string file;   // a part of the path the message must name
  std::string where;  // and the line, frame or value ("" for a file-level rule)
  // The argument the tool gets, from the damaged copy (default: the copy).
  std::function<std::string(const std::string& dir)> arg;
  std::vector<std::string> options = {};  // more command-line options ("@ARG" at the start: the argument)
  std::string stdout_to = {};  // where standard output goes (default: a file of the work folder)
  size_t memory_mb = 0;  // the tool's address space limited to it (0: not), for files of gigabytes
};

struct Outcome {
  bool signaled = false, timed_out = false;
  int code = 0, signal = 0;
  std::string err;
};

// Runs argv in `cwd` (stdout to out_path, stderr captured), killed at
// `timeout_s`, its address space limited to `memory_mb` (0: not).
Outcome run(const std::vector<std::string>& argv, const std::string& cwd, const std::string& out_path,
            double timeout_s, size_t memory_mb = 0) {
  const std::string err_path = cwd + "/stderr.txt";
  std::fflush(stdout);  // else the child's freopen writes our buffered lines again
  const pid_t pid = ::fork();
  if (pid == 0) {
    if (::chdir(cwd.c_str()) != 0) _exit(126);
    if (!std::freopen(out_path.c_str(), "wb", stdout) || !std::freopen(err_path.c_str(), "wb", stderr)) _exit(126);
    if (memory_mb > 0) {
      const rlimit limit{static_cast<rlim_t>(memory_mb) << 20, static_cast<rlim_t>(memory_mb) << 20};
      if (::setrlimit(RLIMIT_AS, &limit) != 0) _exit(126);
    }
    std::vector<char*> a;
    for (const std::string& s : argv) a.push_back(const_cast<char*>(s.c_str()));
    a.push_back(nullptr);
    ::execv(a[0], a.data());
    _exit(127);
  }
  Outcome o;
  int status = 0;
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  for (;;) {
    if (::waitpid(pid, &status, WNOHANG) == pid) break;
    if (std::chrono::steady_clock::now() > end) {
      ::kill(pid, SIGKILL);
      ::waitpid(pid, &status, 0);
      o.timed_out = true;
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  o.signaled = !o.timed_out && WIFSIGNALED(status);
  o.signal = o.signaled ? WTERMSIG(status) : 0;
  o.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  o.err = read_text(err_path);
  return o;
}

// The status column (5th) of an estimates CSV, OR-ed over its rows.
unsigned status_flags(const std::string& csv) {
  unsigned flags = 0;
  const std::vector<std::string> rows = read_lines(csv);
  for (size_t i = 1; i < rows.size(); ++i) {
    size_t at = 0;
    for (int c = 0; c < 4 && at != std::string::npos; ++c) at = rows[i].find(',', at) + 1;
    if (at != std::string::npos && at != 0) flags |= static_cast<unsigned>(std::strtoul(rows[i].c_str() + at, nullptr, 10));
  }
  return flags;
}

// ---- damage helpers ------------------------------------------------------------

// Row `k` (0-based, after the header) of a data.csv: its 1-based line.
size_t line_of_row(size_t k) { return k + 2; }

// The image of row `k` of camera `cam` in REC.
std::string image_of(const std::string& rec, int cam, size_t k) {
  const std::string dir = rec + "/mav0/cam" + std::to_string(cam);
  const std::string row = read_lines(dir + "/data.csv").at(line_of_row(k) - 1);
  std::string name = row.substr(row.find(',') + 1);
  while (!name.empty() && (name.back() == '\r' || name.back() == ' ')) name.pop_back();
  return dir + "/data/" + name;
}

std::string frame_name(const std::string& rec, int cam, size_t k) {
  const std::string p = image_of(rec, cam, k);
  return p.substr(p.find_last_of('/') + 1);
}

size_t rows_of(const std::string& csv) { return read_lines(csv).size() - 1; }

// A PNG of any colour type and depth, filled with a ramp.
void write_png(const std::string& path, int w, int h, int depth, int color) {
  std::FILE* f = std::fopen(path.c_str(), "wb");
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png_create_info_struct(png);
  png_init_io(png, f);
  png_set_IHDR(png, info, static_cast<png_uint_32>(w), static_cast<png_uint_32>(h), depth, color, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_BASE, PNG_FILTER_TYPE_BASE);
  std::vector<png_color> palette(256);
  for (int i = 0; i < 256; ++i) palette[static_cast<size_t>(i)] = {static_cast<png_byte>(i), static_cast<png_byte>(i), static_cast<png_byte>(i)};
  if (color == PNG_COLOR_TYPE_PALETTE) png_set_PLTE(png, info, palette.data(), 256);
  png_write_info(png, info);
  const int channels = color == PNG_COLOR_TYPE_RGB ? 3 : color == PNG_COLOR_TYPE_GRAY_ALPHA ? 2
                       : color == PNG_COLOR_TYPE_RGB_ALPHA                                  ? 4
                                                                                            : 1;
  std::vector<png_byte> row(static_cast<size_t>(w * channels * depth / 8 + 1));
  for (size_t i = 0; i < row.size(); ++i) row[i] = static_cast<png_byte>(i * 7);
  for (int y = 0; y < h; ++y) png_write_row(png, row.data());
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  std::fclose(f);
}

// A PNG whose header claims w x h 8-bit gray pixels and whose data holds a
// few rows only: a few hundred bytes.
void write_png_header_only(const std::string& path, int w, int h) {
  std::FILE* f = std::fopen(path.c_str(), "wb");
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png_create_info_struct(png);
  png_init_io(png, f);
  png_set_IHDR(png, info, static_cast<png_uint_32>(w), static_cast<png_uint_32>(h), 8, PNG_COLOR_TYPE_GRAY,
               PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_BASE, PNG_FILTER_TYPE_BASE);
  png_write_info(png, info);
  std::vector<png_byte> row(static_cast<size_t>(w), 0x55);
  for (int y = 0; y < 4; ++y) png_write_row(png, row.data());
  png_write_flush(png);
  png_destroy_write_struct(&png, &info);
  std::fclose(f);
}

void truncate_file(const std::string& path, size_t keep) {
  const std::string b = read_text(path);
  write_text(path, b.substr(0, std::min(keep, b.size())));
}

void replace_by_folder(const std::string& p) {
  fs::remove(p);
  fs::create_directory(p);
}

// Every line of a text file passed through f.
void edit_lines(const std::string& path, const std::function<std::string(const std::string&)>& f) {
  std::vector<std::string> l = read_lines(path);
  for (std::string& s : l) s = f(s);
  write_lines(path, l);
}

// Keeps the header and the first `n` rows of cam0's and cam1's data.csv.
void keep_frames(const std::string& rec, size_t n) {
  for (const char* cam : {"cam0", "cam1"}) {
    const std::string csv = rec + "/mav0/" + cam + "/data.csv";
    std::vector<std::string> l = read_lines(csv);
    l.resize(std::min(l.size(), n + 1));
    write_lines(csv, l);
  }
}

// Sets the value of `key:` in a sensor.yaml (its whole line).
void set_yaml(const std::string& yaml, const std::string& key, const std::string& value) {
  edit_lines(yaml, [&](const std::string& l) { return l.rfind(key + ":", 0) == 0 ? key + ": " + value : l; });
}

// The key set to value, added at the end where the file has no such line.
void put_yaml(const std::string& yaml, const std::string& key, const std::string& value) {
  const std::string text = read_text(yaml);
  if (text.find("\n" + key + ":") == std::string::npos && text.rfind(key + ":", 0) != 0)
    write_text(yaml, text + key + ": " + value + "\n");
  else
    set_yaml(yaml, key, value);
}

// Number `i` (0-based, row-major) of T_BS.data in a sensor.yaml: where it starts and ends.
std::pair<size_t, size_t> tbs_number(const std::string& text, int i) {
  size_t at = text.find("data: [") + 7;
  for (int k = 0; k < i; ++k) at = text.find(',', at) + 1;
  at = text.find_first_not_of(" \n", at);
  return {at, text.find_first_of(",]", at)};
}

std::string get_tbs(const std::string& yaml, int i) {
  const std::string t = read_text(yaml);
  const auto [a, b] = tbs_number(t, i);
  return t.substr(a, b - a);
}

void set_tbs(const std::string& yaml, int i, const std::string& value) {
  std::string t = read_text(yaml);
  const auto [a, b] = tbs_number(t, i);
  write_text(yaml, t.replace(a, b - a, value));
}

std::string fixture_number(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.17g", v);
  return b;
}

// ---- the recording cases -------------------------------------------------------

std::string n(size_t v) { return std::to_string(v); }

std::vector<Case> recording_cases(const std::string& base) {
  const std::string m = "/mav0/";
  const size_t frames = rows_of(base + m + "cam0/data.csv");
  const size_t mid = frames / 2;                                // a frame in the middle
  const size_t imu_mid = rows_of(base + m + "imu0/data.csv") / 2;
  const std::string mid_frame = "frame " + n(mid);
  const std::string mid_line = ":" + n(line_of_row(mid)) + ":";
  const std::string imu_line = ":" + n(line_of_row(imu_mid)) + ":";
  const std::string c0 = "cam0/data.csv", imu = "imu0/data.csv", gt = "state_groundtruth_estimate0/data.csv";
  const std::string y0 = "cam0/sensor.yaml", y1 = "cam1/sensor.yaml", yi = "imu0/sensor.yaml";
  auto img0 = [mid](const std::string& r) { return image_of(r, 0, mid); };
  auto img1 = [mid](const std::string& r) { return image_of(r, 1, mid); };
  auto both_csv = [m](const std::string& r, const std::function<void(const std::string&)>& f) {
    f(r + m + "cam0/data.csv");
    f(r + m + "cam1/data.csv");
  };
  std::vector<Case> c;
  auto refused = [&](std::string name, std::function<void(const std::string&)> d, std::string file, std::string where) {
    c.push_back({std::move(name), "run", std::move(d), Expect::kRefused, std::move(file), std::move(where), {}});
  };
  auto same = [&](std::string name, std::function<void(const std::string&)> d) {
    c.push_back({std::move(name), "run", std::move(d), Expect::kSame, "", "", {}});
  };
  auto flagged = [&](std::string name, std::function<void(const std::string&)> d) {
    c.push_back({std::move(name), "run", std::move(d), Expect::kFlagged, "", "", {}});
  };
  auto sensor_size = [m](const std::string& r) {
    const std::string y = read_text(r + m + "cam0/sensor.yaml");
    const size_t at = y.find("resolution: [") + 13;
    return std::pair<int, int>{std::stoi(y.substr(at)), std::stoi(y.substr(y.find(',', at) + 1))};
  };

  // PNG frames.
  refused("PNG truncated", [=](const std::string& r) { truncate_file(img0(r), 60); }, img0(base).substr(base.size() + 6), mid_frame);
  refused("PNG zero bytes", [=](const std::string& r) { truncate_file(img1(r), 0); }, "cam1/data/", mid_frame);
  refused("not a PNG (text)", [=](const std::string& r) { write_text(img0(r), "hello\n"); }, "cam0/data/", mid_frame);
  for (const auto& [what, depth, color] : std::vector<std::tuple<std::string, int, int>>{
           {"16-bit", 16, PNG_COLOR_TYPE_GRAY}, {"1-bit", 1, PNG_COLOR_TYPE_GRAY},
           {"paletted", 8, PNG_COLOR_TYPE_PALETTE}, {"RGB", 8, PNG_COLOR_TYPE_RGB},
           {"grayscale+alpha", 8, PNG_COLOR_TYPE_GRAY_ALPHA}, {"RGBA", 8, PNG_COLOR_TYPE_RGB_ALPHA}}) {
    refused("PNG " + what, [=, depth = depth, color = color](const std::string& r) {
      const auto [w, h] = sensor_size(r);
      write_png(img0(r), w, h, depth, color);
    }, "cam0/data/", mid_frame);
  }
  refused("PNG wrong size (mid frame)", [=](const std::string& r) {
    const auto [w, h] = sensor_size(r);
    write_png(img1(r), w + 1, h, 8, PNG_COLOR_TYPE_GRAY);
  }, "cam1/data/", mid_frame);
  refused("PNG wrong size (first frame)", [=](const std::string& r) {
    const auto [w, h] = sensor_size(r);
    write_png(image_of(r, 0, 0), w, h - 1, 8, PNG_COLOR_TYPE_GRAY);
  }, "cam0/data/", "frame 0");
  // Refused by its header, not decoded (was: 256 MB allocated per decoding
  // thread, then "corrupt PNG: Not enough image data", naming no size).
  refused("PNG header claims 16384x16384 (a small file)", [=](const std::string& r) { write_png_header_only(img0(r), 16384, 16384); },
          "cam0/data/", "16384x16384");
  refused("PNG 16000x16000", [=](const std::string& r) { write_png(img0(r), 16000, 16000, 8, PNG_COLOR_TYPE_GRAY); },
          "cam0/data/", mid_frame);
  // Sparse: no disk space taken (was: "error: std::bad_alloc", naming nothing).
  refused("frame a 100 GB file", [=](const std::string& r) { fs::resize_file(img0(r), uintmax_t{100} << 30); },
          "cam0/data/", mid_frame);
  refused("frame file missing", [=](const std::string& r) { fs::remove(img1(r)); }, "cam1/data.csv", mid_line);
  refused("folder where a frame is", [=](const std::string& r) { replace_by_folder(img0(r)); }, c0, mid_line);
  refused("frame a symlink loop", [=](const std::string& r) {
    fs::remove(img0(r));
    fs::create_symlink(frame_name(r, 0, mid), img0(r));
  }, c0, mid_line);
  refused("cam1 at another resolution", [=](const std::string& r) {
    const auto [w, h] = sensor_size(r);
    for (size_t k = 0; k < frames; ++k) write_png(image_of(r, 1, k), w / 2, h / 2, 8, PNG_COLOR_TYPE_GRAY);
    set_yaml(r + m + y1, "resolution", "[" + n(static_cast<size_t>(w / 2)) + ", " + n(static_cast<size_t>(h / 2)) + "]");
    edit_lines(r + m + y1, [&](const std::string& l) {
      return l.rfind("intrinsics:", 0) == 0 ? "intrinsics: [" + n(static_cast<size_t>(w / 2)) + ", " +
                                                  n(static_cast<size_t>(w / 2)) + ", " + n(static_cast<size_t>(w / 4)) +
                                                  ", " + n(static_cast<size_t>(h / 4)) + "]"
                                            : l;
    });
  }, y1, "resolution");
  {
    Case k = c.back();  // at a working size both sensors can give, it ran (E 99.5 %)
    k.name += ", --width 16 --height 12";
    k.options = {"--width", "16", "--height", "12"};
    c.push_back(k);
  }

  // data.csv.
  refused("CSV header missing", [=](const std::string& r) { fixture::erase_line(r + m + c0, 1); }, c0, ":1:");
  refused("CSV extra column", [=](const std::string& r) { fixture::set_line(r + m + c0, line_of_row(mid), read_lines(r + m + c0)[line_of_row(mid) - 1] + ",x"); }, c0, mid_line);
  refused("CSV missing column", [=](const std::string& r) {
    const std::string l = read_lines(r + m + imu)[line_of_row(imu_mid) - 1];
    fixture::set_line(r + m + imu, line_of_row(imu_mid), l.substr(0, l.find_last_of(',')));
  }, imu, imu_line);
  refused("CSV NUL inside a filename", [=](const std::string& r) {
    set_field(r + m + c0, line_of_row(mid), 1, frame_name(r, 0, mid) + std::string("\0junk", 5));
  }, c0, mid_line);  // was: exit 0, the frame before the NUL read
  // A frame file named by two rows (was: exit 0, the repeated frame read as a standstill).
  refused("CSV one frame file named twice", [=](const std::string& r) { set_field(r + m + c0, line_of_row(mid), 1, frame_name(r, 0, mid - 1)); },
          c0, mid_line + " filename '" + frame_name(base, 0, mid - 1) + "' is also the frame of line " + n(line_of_row(mid - 1)));
  // A frame file that is a link to another frame (was: exit 0, E 0.82 -> 1.30 % on wall_40x30).
  refused("CSV a frame file a symlink to another frame", [=](const std::string& r) {
    fs::remove(image_of(r, 0, mid));
    fs::create_symlink(frame_name(r, 0, mid - 1), image_of(r, 0, mid));
  }, c0, mid_line + " filename '" + frame_name(base, 0, mid) + "' is the same file as '" + frame_name(base, 0, mid - 1) + "', the frame of line " + n(line_of_row(mid - 1)));
  refused("CSV non-numeric timestamp", [=](const std::string& r) { set_field(r + m + c0, line_of_row(mid), 0, "abc"); }, c0, mid_line);
  refused("CSV NaN timestamp", [=](const std::string& r) { set_field(r + m + c0, line_of_row(mid), 0, "nan"); }, c0, mid_line);
  refused("CSV negative timestamp", [=](const std::string& r) { both_csv(r, [](const std::string& f) { set_field(f, 2, 0, "-1000000000"); }); }, c0, ":2:");
  refused("CSV timestamp beyond uint64", [=](const std::string& r) { both_csv(r, [&](const std::string& f) { set_field(f, line_of_row(frames - 1), 0, "99999999999999999999"); }); },
          c0, ":" + n(line_of_row(frames - 1)) + ":");
  refused("CSV timestamp beyond int64", [=](const std::string& r) { both_csv(r, [&](const std::string& f) { set_field(f, line_of_row(frames - 1), 0, "9300000000000000000"); }); },
          c0, "9300000000000000000");
  refused("CSV duplicate timestamp", [=](const std::string& r) { both_csv(r, [&](const std::string& f) { set_field(f, line_of_row(mid), 0, read_lines(f)[line_of_row(mid) - 2].substr(0, read_lines(f)[line_of_row(mid) - 2].find(','))); }); },
          c0, mid_line);
  refused("CSV decreasing timestamp", [=](const std::string& r) { set_field(r + m + imu, line_of_row(imu_mid), 0, "1"); }, imu, imu_line);
  refused("CSV trailing garbage line", [=](const std::string& r) { write_text(r + m + c0, read_text(r + m + c0) + "garbage here"); }, c0, ":" + n(frames + 2) + ":");
  refused("CSV very long line", [=](const std::string& r) { write_text(r + m + imu, read_text(r + m + imu) + std::string(4 << 20, '7') + "\n"); }, imu, ":" + n(rows_of(base + m + imu) + 2) + ":");
  refused("CSV very long field", [=](const std::string& r) { set_field(r + m + imu, line_of_row(imu_mid), 3, std::string(1 << 20, 'x')); }, imu, imu_line);
  refused("CSV empty file", [=](const std::string& r) { write_text(r + m + c0, ""); }, c0, ":1:");
  refused("CSV semicolons", [=](const std::string& r) { edit_lines(r + m + imu, [](std::string l) { for (char& ch : l) if (ch == ',') ch = ';'; return l; }); }, imu, ":1:");
  same("CSV CRLF line endings", [=](const std::string& r) { for (const std::string& f : {c0, imu, gt}) edit_lines(r + m + f, [](const std::string& l) { return l + "\r"; }); });
  same("CSV UTF-8 BOM", [=](const std::string& r) { write_text(r + m + imu, "\xEF\xBB\xBF" + read_text(r + m + imu)); });
  same("CSV blank lines", [=](const std::string& r) { edit_lines(r + m + c0, [](const std::string& l) { return l + "\n"; }); });
  same("CSV spaces around fields", [=](const std::string& r) { edit_lines(r + m + imu, [](std::string l) { const size_t at = l.find(','); return l.insert(at, " ").insert(at + 2, " "); }); });

  // The gyro.
  refused("IMU NaN rate", [=](const std::string& r) { set_field(r + m + imu, line_of_row(imu_mid), 3, "nan"); }, imu, imu_line);
  refused("IMU inf rate", [=](const std::string& r) { set_field(r + m + imu, line_of_row(imu_mid), 1, "-inf"); }, imu, imu_line);
  refused("IMU hexadecimal rate 0x10", [=](const std::string& r) { set_field(r + m + imu, line_of_row(imu_mid), 3, "0x10"); }, imu, imu_line);  // was: read as 16 rad/s
  refused("IMU 1e999 rate", [=](const std::string& r) { set_field(r + m + imu, line_of_row(imu_mid), 2, "1e999"); }, imu, imu_line);
  flagged("IMU 1e30 yaw rate (saturates)", [=](const std::string& r) { set_field(r + m + imu, line_of_row(imu_mid), 3, "1e30"); });
  flagged("IMU hole of a third", [=](const std::string& r) {
    std::vector<std::string> l = read_lines(r + m + imu), out;
    for (size_t i = 0; i < l.size(); ++i) if (i == 0 || i < l.size() / 3 || i > 2 * l.size() / 3) out.push_back(l[i]);
    write_lines(r + m + imu, out);
  });
  refused("IMU out of order", [=](const std::string& r) {
    std::vector<std::string> l = read_lines(r + m + imu);
    std::swap(l[line_of_row(imu_mid) - 1], l[line_of_row(imu_mid)]);
    write_lines(r + m + imu, l);
  }, imu, ":" + n(line_of_row(imu_mid) + 1) + ":");
  refused("IMU no samples", [=](const std::string& r) { write_lines(r + m + imu, {read_lines(r + m + imu)[0]}); }, imu, ":2:");
  flagged("IMU one sample", [=](const std::string& r) { std::vector<std::string> l = read_lines(r + m + imu); l.resize(2); write_lines(r + m + imu, l); });

  // Ground truth.
  refused("GT zero quaternion", [=](const std::string& r) { for (size_t k = 4; k <= 7; ++k) set_field(r + m + gt, 3, k, "0"); }, gt, ":3:");
  refused("GT NaN velocity", [=](const std::string& r) { set_field(r + m + gt, 3, 8, "nan"); }, gt, ":3:");
  // Beyond a physical bound (was: exit 0, "RMS error: 1e+06 m/s").
  refused("GT velocity 1e6 m/s", [=](const std::string& r) { set_field(r + m + gt, 3, 8, "1e6"); }, gt, ":3: column 'v_RS_R_x [m s^-1]': 1e+06");
  refused("GT position 1e300 m", [=](const std::string& r) { set_field(r + m + gt, 3, 1, "1e300"); }, gt, ":3: column 'p_RS_R_x [m]': 1e+300");
  refused("GT header only", [=](const std::string& r) { write_lines(r + m + gt, {read_lines(r + m + gt)[0]}); }, gt, ":2:");
  refused("GT a folder", [=](const std::string& r) { fs::remove(r + m + gt); fs::create_directory(r + m + gt); }, gt, "folder");

  // sensor.yaml.
  refused("YAML key missing", [=](const std::string& r) { edit_lines(r + m + y0, [](const std::string& l) { return l.rfind("resolution:", 0) == 0 ? "# no resolution" : l; }); }, y0, "resolution");
  refused("YAML wrong type", [=](const std::string& r) { set_yaml(r + m + y1, "rate_hz", "[fast]"); }, y1, "rate_hz");
  refused("YAML key given twice", [=](const std::string& r) { write_text(r + m + y0, read_text(r + m + y0) + "T_BS:\n  cols: 4\n  rows: 4\n  data: [1, 0, 0, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 0, 0, 1]\n"); }, y0, "T_BS");
  refused("YAML binary garbage", [=](const std::string& r) { std::string g(300, '\0'); for (size_t i = 0; i < g.size(); ++i) g[i] = static_cast<char>(i * 37 + 11); write_text(r + m + y0, g); }, y0, "");
  refused("YAML zero focal length", [=](const std::string& r) { edit_lines(r + m + y0, [](const std::string& l) { return l.rfind("intrinsics:", 0) == 0 ? "intrinsics: [0" + l.substr(l.find(',')) : l; }); }, y0, "fu");
  refused("YAML negative focal length", [=](const std::string& r) { edit_lines(r + m + y1, [](const std::string& l) { return l.rfind("intrinsics:", 0) == 0 ? "intrinsics: [-40" + l.substr(l.find(',')) : l; }); }, y1, "fu");
  refused("YAML fv 1e12", [=](const std::string& r) { edit_lines(r + m + y0, [](const std::string& l) { if (l.rfind("intrinsics:", 0) != 0) return l; const size_t a = l.find(',') + 1; return l.substr(0, a) + " 1e12" + l.substr(l.find(',', a)); }); }, y0, "fv");
  refused("YAML cu outside", [=](const std::string& r) { edit_lines(r + m + y0, [](const std::string& l) { if (l.rfind("intrinsics:", 0) != 0) return l; size_t a = l.find(',') + 1; a = l.find(',', a) + 1; return l.substr(0, a) + " 1e5" + l.substr(l.find(',', a)); }); }, y0, "cu");
  refused("YAML cv outside", [=](const std::string& r) { edit_lines(r + m + y1, [](const std::string& l) { if (l.rfind("intrinsics:", 0) != 0) return l; const size_t end = l.find(']'); return l.substr(0, l.find_last_of(',', end) + 1) + " -1e5" + l.substr(end); }); }, y1, "cv");
  refused("YAML resolution unlike the PNGs", [=](const std::string& r) { set_yaml(r + m + y0, "resolution", "[64, 48]"); set_yaml(r + m + y1, "resolution", "[64, 48]"); }, "cam0/data/", "resolution [64, 48]");
  refused("YAML lens not invertible", [=](const std::string& r) { set_yaml(r + m + y1, "distortion_coefficients", "[-5, 0, 0, 0]"); }, y1, "distortion_coefficients");
  refused("YAML negative exposure", [=](const std::string& r) { put_yaml(r + m + y0, "exposure_s", "-0.01"); }, y0, "exposure_s");
  refused("YAML negative gyro noise density", [=](const std::string& r) { put_yaml(r + m + yi, "gyroscope_noise_density", "-1e-4"); }, yi, "gyroscope_noise_density");
  // "FILE:LINE" of `key:` in a sensor.yaml of the intact recording.
  auto at_key = [&](const std::string& yaml, const std::string& key) {
    const std::vector<std::string> y = read_lines(base + m + yaml);
    size_t line = 0;
    while (line < y.size() && y[line].rfind(key + ":", 0) != 0) ++line;
    return yaml + ":" + n(line + 1) + ":";
  };
  // More pixels than lumavel bins (was: refused at frame 0, "cannot bin to the working resolution", no rule said).
  refused("YAML resolution 16384x16384", [=](const std::string& r) { set_yaml(r + m + y0, "resolution", "[16384, 16384]"); set_yaml(r + m + y1, "resolution", "[16384, 16384]"); },
          at_key(y0, "resolution"), "[16384, 16384] is 268435456 pixels: lumavel bins frames of at most 16777216 pixels");
  // k1 = 50 folds the undistortion map: refused at the coefficients' line (was: the file only).
  refused("YAML k1 = 50", [=](const std::string& r) { set_yaml(r + m + y0, "distortion_coefficients", "[50, 0, 0, 0]"); },
          at_key(y0, "distortion_coefficients"), "[50, 0, 0, 0]");
  // With one frame (one gyro sample) the period is 1 / rate_hz: refused at its line (was: the file only).
  refused("YAML rate_hz 1e-300, one frame", [=](const std::string& r) { set_yaml(r + m + y0, "rate_hz", "1e-300"); keep_frames(r, 1); },
          at_key(y0, "rate_hz"), "frame period");
  refused("YAML imu rate_hz 1e-300, one gyro sample", [=](const std::string& r) {
    set_yaml(r + m + yi, "rate_hz", "1e-300");
    std::vector<std::string> l = read_lines(r + m + imu);
    write_lines(r + m + imu, {l[0], l[l.size() / 4]});
  }, at_key(yi, "rate_hz"), "gyro gap");
  refused("YAML lens p1 = 3", [=](const std::string& r) { set_yaml(r + m + y0, "distortion_coefficients", "[0, 0, 3, 0]"); }, y0, "distortion_coefficients");
  // Column 0 of the rotation (numbers 0, 4, 8) doubled, or negated: a mirror.
  auto scale_column0 = [](const std::string& yaml, double by) {
    for (int i : {0, 4, 8}) set_tbs(yaml, i, fixture_number(std::stod(get_tbs(yaml, i)) * by));
  };
  refused("YAML T_BS scaled", [=](const std::string& r) { scale_column0(r + m + y0, 2); }, y0, "T_BS");
  refused("YAML T_BS a reflection", [=](const std::string& r) { scale_column0(r + m + y1, -1); }, y1, "T_BS");
  refused("YAML T_BS 15 numbers", [=](const std::string& r) { replace_in(r + m + yi, "0, 0, 0, 1]", "0, 0, 0]"); }, yi, "T_BS");
  refused("YAML baseline zero", [=](const std::string& r) { set_tbs(r + m + y0, 3, get_tbs(r + m + y1, 3)); }, y0, "T_BS");
  refused("YAML baseline 10 m", [=](const std::string& r) { set_tbs(r + m + y1, 3, "10"); }, "sensor.yaml", "baseline");
  // Values read but not estimated with (was: exit 0, 1e300 taken as it was).
  refused("YAML camera 1000 m from the body origin", [=](const std::string& r) { set_tbs(r + m + y1, 3, "1000"); }, y1, "T_BS: translation (1000");
  refused("YAML imu T_BS translation 1e300", [=](const std::string& r) { set_tbs(r + m + yi, 11, "1e300"); }, yi, "translation");
  refused("YAML exposure 1e300 s", [=](const std::string& r) { put_yaml(r + m + y0, "exposure_s", "1e300"); }, y0, "exposure_s = 1e+300");
  refused("YAML gyro noise density 1e300", [=](const std::string& r) { put_yaml(r + m + yi, "gyroscope_noise_density", "1e300"); }, yi, "gyroscope_noise_density = 1e+300");
  refused("YAML rate_hz 1e300", [=](const std::string& r) { set_yaml(r + m + y1, "rate_hz", "1e300"); }, at_key(y1, "rate_hz"), "1e+300");
  refused("YAML baseline along y", [=](const std::string& r) { set_tbs(r + m + y1, 7, "3"); }, y0, "T_BS");
  refused("cam1 missing entirely", [=](const std::string& r) { fs::remove_all(r + m + "cam1"); }, y1, "");
  refused("mav0 a file", [=](const std::string& r) { fs::remove_all(r + "/mav0"); write_text(r + "/mav0", "x"); }, "mav0", "file");

  // Recordings of 0, 1 and 2 frames.
  refused("0 frames", [=](const std::string& r) { keep_frames(r, 0); }, c0, ":2:");
  flagged("1 frame", [=](const std::string& r) { keep_frames(r, 1); });
  flagged("2 frames", [=](const std::string& r) { keep_frames(r, 2); });

  // What a user passes.
  c.push_back({"REC/mav0/cam0 given", "run", nullptr, Expect::kRefused, "mav0/cam0", "sensor", [](const std::string& r) { return r + "/mav0/cam0"; }});
  c.push_back({"a file given", "run", nullptr, Expect::kRefused, "cam0/data.csv", "file", [](const std::string& r) { return r + "/mav0/cam0/data.csv"; }});
  c.push_back({"a folder that is no recording", "run", nullptr, Expect::kRefused, "/data", "not a recording", [](const std::string& r) { return r + "/mav0/cam0/data"; }});
  c.push_back({"REC/mav0 given", "run", nullptr, Expect::kSame, "", "", [](const std::string& r) { return r + "/mav0/"; }});
  c.push_back({"path with spaces", "run", [](const std::string& r) { fs::rename(r, r + " with spaces"); fs::create_directory(r); }, Expect::kSame, "", "", [](const std::string& r) { return r + " with spaces"; }});
  c.push_back({"symlink loop as REC", "run", [](const std::string& r) { fs::create_symlink(r + "/loop_b", r + "/loop_a"); fs::create_symlink(r + "/loop_a", r + "/loop_b"); }, Expect::kRefused, "loop_a", "loop", [](const std::string& r) { return r + "/loop_a"; }});

  // --help is output too (was: exit 0, the help lost, nothing said).
  c.push_back({"--help to a full standard output", "run", nullptr, Expect::kRefused, "lumavel-sim run: error: standard output",
               "write error", {}, {"--help"}, "/dev/full"});

  // Beyond the clock's range the deadline overflowed: it ended at once, exit 0.
  c.push_back({"--hid-linger 1e300", "run", nullptr, Expect::kRefused, "--hid-linger", "1e300", {},
               {"--hid", "file:/dev/null", "--hid-linger", "1e300"}});

  // An option's number is decimal, as a file's: strtod read '0x1p-5' as 0.03125.
  c.push_back({"--hid-linger in hexadecimal", "run", nullptr, Expect::kRefused, "--hid-linger", "0x0", {},
               {"--hid", "file:/dev/null", "--hid-linger", "0x0"}});

  // calibrate reads the recording the same way.
  for (const char* name : {"PNG truncated", "YAML key given twice", "cam1 at another resolution", "CSV timestamp beyond int64"})
    for (const Case& k : std::vector<Case>(c))
      if (k.name == name) {
        Case cal = k;
        cal.name = "calibrate: " + k.name;
        cal.tool = "calibrate";
        c.push_back(cal);
      }
  return c;
}

// ---- the slider dataset (import-slider) ------------------------------------------

void write_slider(const std::string& dir) {
  fs::create_directories(dir + "/images");
  std::string images, gt;
  for (int i = 0; i < 12; ++i) {
    char name[64];
    std::snprintf(name, sizeof name, "images/frame_%08d.png", i);
    std::vector<uint8_t> px(48 * 36);
    for (int v = 0; v < 36; ++v)
      for (int u = 0; u < 48; ++u) px[static_cast<size_t>(v * 48 + u)] = static_cast<uint8_t>(128 + 90 * std::sin(0.45 * (u + 3 * i)));
    lumavel::host::write_png_gray(dir + "/" + name, px.data(), 48, 36);
    char row[96];
    std::snprintf(row, sizeof row, "%.6f %s\n", 0.01 + 0.04 * i, name);
    images += row;
  }
  for (int k = 0; k <= 50; ++k) {
    char row[96];
    std::snprintf(row, sizeof row, "%.6f %.9f 0.0 0.0 0.0 0.0 0.0 1.0\n", 0.01 * k, 0.1 + 0.25 * 0.01 * k);
    gt += row;
  }
  write_text(dir + "/images.txt", images);
  write_text(dir + "/groundtruth.txt", gt);
  write_text(dir + "/calib.txt", "50 51 23.5 17.5 -0.1 0.05 0.001 -0.002 0\n");
}

std::vector<Case> slider_cases() {
  std::vector<Case> c;
  auto refused = [&](std::string name, std::function<void(const std::string&)> d, std::string file, std::string where) {
    c.push_back({"import: " + name, "import", std::move(d), Expect::kRefused, std::move(file), std::move(where), {}});
  };
  auto line5 = [](const std::string& path, const std::function<std::string(const std::string&)>& f) {
    fixture::set_line(path, 5, f(read_lines(path)[4]));
  };
  refused("time '0.17abc'", [=](const std::string& d) { line5(d + "/images.txt", [](std::string l) { return l.insert(l.find(' '), "abc"); }); }, "images.txt", ":5:");
  refused("negative time", [=](const std::string& d) { line5(d + "/images.txt", [](const std::string& l) { return "-5" + l.substr(l.find(' ')); }); }, "images.txt", ":5:");
  refused("time 1e300 s", [=](const std::string& d) { line5(d + "/groundtruth.txt", [](const std::string& l) { return "1e300" + l.substr(l.find(' ')); }); }, "groundtruth.txt", ":5:");
  // The recording's physical bounds (was: exit 0, a speed of 2.5e301 m/s written).
  refused("position 1e300 m", [=](const std::string& d) { line5(d + "/groundtruth.txt", [](const std::string& l) { const size_t a = l.find(' ') + 1; return l.substr(0, a) + "1e300" + l.substr(l.find(' ', a)); }); },
          "groundtruth.txt", ":5: x: 1e+300 m is beyond");
  refused("position jump of 1e5 m", [=](const std::string& d) { line5(d + "/groundtruth.txt", [](const std::string& l) { const size_t a = l.find(' ') + 1; return l.substr(0, a) + "1e5" + l.substr(l.find(' ', a)); }); },
          "groundtruth.txt", ":5: x = 100000 m is 99999.9 m from line 1's 0.1 m: a linear slider's track is at most 10 m");
  // strtod's hexadecimal form, as the recording tables refuse it (was: read, exit 0).
  refused("hexadecimal position", [=](const std::string& d) { line5(d + "/groundtruth.txt", [](const std::string& l) { const size_t a = l.find(' ') + 1; return l.substr(0, a) + "0x1p-3" + l.substr(l.find(' ', a)); }); },
          "groundtruth.txt", ":5: column 'x': '0x1p-3' is a hexadecimal");
  refused("hexadecimal calib fx", [=](const std::string& d) { write_text(d + "/calib.txt", "0x32 51 23.5 17.5 0 0 0 0 0\n"); }, "calib.txt", ":1: column 'fx'");
  refused("extra ground-truth field", [=](const std::string& d) { line5(d + "/groundtruth.txt", [](const std::string& l) { return l + " 7"; }); }, "groundtruth.txt", ":5:");
  refused("zero quaternion", [=](const std::string& d) { line5(d + "/groundtruth.txt", [](const std::string& l) { return l.substr(0, l.size() - 3) + "0.0"; }); }, "groundtruth.txt", ":5:");
  refused("extra calib field", [=](const std::string& d) { write_text(d + "/calib.txt", "50 51 23.5 17.5 0 0 0 0 0 9\n"); }, "calib.txt", ":1:");
  refused("calib cy 1e6", [=](const std::string& d) { write_text(d + "/calib.txt", "50 51 23.5 1e6 0 0 0 0 0\n"); }, "calib.txt", "cv");
  refused("calib k1 1e10", [=](const std::string& d) { write_text(d + "/calib.txt", "50 51 23.5 17.5 1e10 0 0 0 0\n"); }, "calib.txt", "distortion");
  refused("image missing", [=](const std::string& d) { fs::remove(d + "/images/frame_00000004.png"); }, "images.txt", ":5:");
  refused("image truncated", [=](const std::string& d) { truncate_file(d + "/images/frame_00000004.png", 70); }, "images.txt", ":5:");
  refused("image of another size", [=](const std::string& d) { write_png(d + "/images/frame_00000004.png", 40, 36, 8, PNG_COLOR_TYPE_GRAY); }, "images.txt", ":5:");
  refused("image RGB", [=](const std::string& d) { write_png(d + "/images/frame_00000004.png", 48, 36, 8, PNG_COLOR_TYPE_RGB); }, "images.txt", ":5:");
  // As a recording's frame named by two rows (was: exit 0, the repeated frame read as a standstill).
  refused("image named twice", [=](const std::string& d) { line5(d + "/images.txt", [](const std::string& l) { return l.substr(0, l.find(' ')) + " images/frame_00000003.png"; }); },
          "images.txt", ":5: filename 'images/frame_00000003.png' is also the frame of line 4");
  // Only the focal lengths' ratio was checked: written, exit 0, and run refused the recording; then
  // refused after the import, the recording left behind; now before anything is written.
  refused("calib fx fy 1e300", [=](const std::string& d) { write_text(d + "/calib.txt", "1e300 1e300 23.5 17.5 0 0 0 0 0\n"); },
          "the recording it makes is one lumavel-sim run refuses (nothing written)", "cam0/sensor.yaml: intrinsics (at the working resolution): focal length fu");
  // The folder itself (was: '.../nowhere/images.txt: does not exist', as if only the file were missing).
  c.push_back({"import: dataset folder missing", "import", nullptr, Expect::kRefused, "/nowhere: does not exist", "", [](const std::string& d) { return d + "/nowhere"; }});
  c.push_back({"import: dataset folder a file", "import", nullptr, Expect::kRefused, "calib.txt: is a file, not a dataset folder", "", [](const std::string& d) { return d + "/calib.txt"; }});
  refused("NUL inside an image name", [=](const std::string& d) { line5(d + "/images.txt", [](const std::string& l) { return l + std::string("\0junk", 5); }); }, "images.txt", ":5:");  // was: exit 0
  c.push_back({"import: groundtruth.txt of 4 GB", "import", [](const std::string& d) {  // as config: a 4 GB file
    fs::resize_file(d + "/groundtruth.txt", uintmax_t{4} << 30);
  }, Expect::kRefused, "groundtruth.txt", "line is longer than", {}, {}, {}, 1024});
  refused("empty images.txt", [=](const std::string& d) { write_text(d + "/images.txt", ""); }, "images.txt", "");
  c.push_back({"import: BOM and CRLF", "import", [](const std::string& d) {
    write_text(d + "/images.txt", "\xEF\xBB\xBF" + read_text(d + "/images.txt"));
    edit_lines(d + "/groundtruth.txt", [](const std::string& l) { return l + "\r"; });
  }, Expect::kSame, "", "", {}});
  c.push_back({"import: image name with spaces", "import", [](const std::string& d) {
    fs::rename(d + "/images/frame_00000004.png", d + "/images/frame 4.png");
    fixture::set_line(d + "/images.txt", 5, read_lines(d + "/images.txt")[4].substr(0, 9) + "images/frame 4.png");
  }, Expect::kSame, "", "", {}});
  return c;
}

// ---- configuration and report files (lumavel-read) -----------------------------------

std::vector<Case> read_cases(const std::string& report) {
  std::vector<Case> c;
  auto config = [&](std::string name, std::string text, std::string where) {
    c.push_back({"config: " + name, "config", [text](const std::string& d) { write_text(d + "/rig.cfg", text); },
                 Expect::kRefused, "rig.cfg", std::move(where), {}});
  };
  config("not a number", "width=40\ntau_us=fast\n", ":2:");
  config("key twice", "width=40\nwidth=80\n", ":2:");
  config("NaN", "baseline_m=nan\n", ":1:");
  config("beyond int64", "tau_us=99999999999999999999999\n", ":1:");
  config("no KEY=VALUE", "width 40\n", ":1:");
  config("only comments", "# nothing\n\n", "no KEY=VALUE");
  config("trailing comment", "width=40 # columns\n", ":1:");
  config("hexadecimal baseline", "baseline_m=0x1p-4\n", ":1: baseline_m = 0x1p-4: a hexadecimal");  // was: ok (0.0625 m)
  config("hexadecimal lens value", "width=16\nlens_cam0=0x1p-9,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0\n", ":2: lens_cam0 value 1");
  // As a recording table's (was: "width = 40height=30: not a whole number").
  config("CR-only line ends", "width=40\rheight=30\r", ":1: a carriage return (CR) inside the line, at character 9");
  config("lens table short", "width=40\nlens_cam0=0,0,0\n", ":2:");
  // A binary file's bytes as \xNN (was: sent to the terminal as they were, escape sequences and all).
  config("binary garbage", "width=40\n\x1b[2J\x07\x01garbage\n\x1b]0;title\x07=1\n", ":2: \"\\x1B[2J\\x07\\x01garbage\" is not KEY=VALUE");
  config("binary garbage as a key", "\x1b]0;title\x07=1\n", ":1: unknown configuration key \"\\x1B]0;title\\x07\"");
  // --file takes several names (was: "width=80: does not exist", no more said).
  c.push_back({"config: a setting after --file FILE", "config", [](const std::string& d) { write_text(d + "/rig.cfg", "width=40\n"); },
               Expect::kRefused, "width=80", "give the settings before --file", {}, {"width=80"}});
  // As in a file (was: the last one taken, 'ok', exit 0).
  c.push_back({"config: a key twice on the command line", "config", [](const std::string& d) { write_text(d + "/rig.cfg", "height=30\n"); },
               Expect::kRefused, "command line: width=80", "width is given again (first as width=40)", {}, {"--", "width=40", "width=80"}});
  auto replay = [&](std::string name, std::function<std::string(const std::string&)> bytes, std::string where) {
    c.push_back({"replay: " + name, "replay", [bytes, report](const std::string& d) { write_text(d + "/run.hidrep", bytes(read_text(report))); },
                 Expect::kRefused, "run.hidrep", std::move(where), {}});
  };
  replay("truncated", [](const std::string& b) { return b.substr(0, b.size() / 2 + 3); }, "record");
  replay("bit flipped", [](std::string b) { b[b.size() / 2] = static_cast<char>(b[b.size() / 2] ^ 0x20); return b; }, "record");
  replay("zero-length record", [](const std::string& b) { return b + std::string(1, '\0'); }, "record");
  // Records 43 bytes long (1 + 42): one missing, two swapped (was: 'lost 1 report(s) ... (host too slow, or
  // reconnect)', exit 0, a row missing from the CSV).
  replay("a record missing", [](const std::string& b) { return b.substr(0, 8 + 5 * 43) + b.substr(8 + 6 * 43); },
         "record 6 at byte 223 (records missing: a damaged report file");
  replay("two records swapped", [](const std::string& b) { return b.substr(0, 8 + 5 * 43) + b.substr(8 + 6 * 43, 43) + b.substr(8 + 5 * 43, 43) + b.substr(8 + 7 * 43); },
         "record 7 at byte 266 (records out of order: a damaged report file)");
  // A record whose CRC holds (re-encoded) but that goes back against the one
  // before: its frame's time, its frame number (was: written as it was, exit 0).
  const auto rewritten = [](std::string b, size_t record,
                            const std::function<void(lumavel::protocol::Measurement&, const lumavel::protocol::Measurement&)>& edit) {
    const auto at = [&b](size_t r) { return reinterpret_cast<uint8_t*>(&b[8 + (r - 1) * 43 + 1]); };
    lumavel::protocol::Measurement before{}, m{};
    lumavel::protocol::decode_measurement(at(record - 1), 42, before);
    lumavel::protocol::decode_measurement(at(record), 42, m);
    edit(m, before);
    lumavel::protocol::encode_measurement(m, at(record), 42);
    return b;
  };
  {
    std::string intact = read_text(report);
    lumavel::protocol::Measurement fifth{};
    lumavel::protocol::decode_measurement(reinterpret_cast<const uint8_t*>(&intact[8 + 4 * 43 + 1]), 42, fifth);
    const std::string t5 = std::to_string(fifth.t_ns);
    replay("a record's t_ns not after the one before", [=](const std::string& b) {
      return rewritten(b, 6, [](auto& m, const auto& before) { m.t_ns = before.t_ns; });
    }, "record 6 at byte 223: t_ns " + t5 + " is not after the previous report's (" + t5 + ")");
    replay("a record's frame_index going back", [=](const std::string& b) {
      return rewritten(b, 6, [](auto& m, const auto&) { m.frame_index = 1; });
    }, "record 6 at byte 223: frame_index 1 is not after the previous report's (4)");
  }
  // A mailbox reply (a feature chunk, id 0x84) is never written to a report
  // file: there it is damage (was: skipped unsaid, exit 0; as the last record,
  // that measurement missing from the CSV).
  {
    const size_t last = read_text(report).size() - 43;
    replay("the last record a mailbox reply", [](std::string b) { b[b.size() - 42] = '\x84'; return b; },
           "record " + std::to_string((last - 8) / 43 + 1) + " at byte " + std::to_string(last) + " (id 0x84, 42 bytes): a mailbox reply");
  }
  // The second-to-last record's length byte 42 -> 85: it takes the last
  // record as its tail (was: decoded from its first 42 bytes, exit 0, the last
  // measurement missing from the CSV).
  {
    const size_t at = read_text(report).size() - 2 * 43;
    replay("a length byte that swallows the last record", [at](std::string b) { b[at] = '\x55'; return b; },
           "record " + std::to_string((at - 8) / 43 + 1) + " at byte " + std::to_string(at) +
               " (id 0x01, 85 bytes): longer than a measurement report (42 bytes)");
  }
  // Cut after its header (was: a CSV of the header line, exit 0).
  replay("the header alone", [](const std::string& b) { return b.substr(0, 8); },
         "run.hidrep: no record after its \"LMVHID1\" header: a run writes a report for every frame pair, at least one");
  replay("no magic", [](const std::string& b) { return b.substr(8); }, "not a lumavel report file");
  replay("empty", [](const std::string&) { return std::string(); }, "not a lumavel report file");
  // 4 GB (sparse) of NUL bytes, the tool limited to 1 GB (was: read whole:
  // "error: std::bad_alloc", or minutes and gigabytes without the limit).
  c.push_back({"config: a 4 GB file", "config", [](const std::string& d) {
    write_text(d + "/rig.cfg", "width=40\n");
    fs::resize_file(d + "/rig.cfg", uintmax_t{4} << 30);
  }, Expect::kRefused, "rig.cfg", "4294967296 bytes", {}, {}, {}, 1024});
  // Output lost to a full disk (was: exit 0, nothing said).
  c.push_back({"replay: CSV to a full standard output", "replay", [report](const std::string& d) { write_text(d + "/run.hidrep", read_text(report)); },
               Expect::kRefused, "standard output", "write error", {}, {"-o", "-"}, "/dev/full"});
  c.push_back({"config: 'ok' to a full standard output", "config", [](const std::string& d) { write_text(d + "/rig.cfg", "width=40\n"); },
               Expect::kRefused, "standard output", "write error", {}, {}, "/dev/full"});
  // --help is output too (was: exit 0, the help lost, nothing said).
  c.push_back({"config: --help to a full standard output", "config", [](const std::string& d) { write_text(d + "/rig.cfg", "width=40\n"); },
               Expect::kRefused, "lumavel-read config check: error: standard output", "write error", {}, {"--help"}, "/dev/full"});
  // The CSV written over the report file being read (was: exit 0, the report file gone).
  for (const char* to : {"run.hidrep", "link.csv"}) {
    c.push_back({std::string("replay: -o onto the report file") + (to[0] == 'l' ? " (a symlink to it)" : ""), "replay",
                 [report](const std::string& d) {
                   write_text(d + "/run.hidrep", read_text(report));
                   fs::create_symlink("run.hidrep", d + "/link.csv");
                 },
                 Expect::kRefused, "run.hidrep", "-o", {}, {"-o", std::string("@ARG/") + to}});
  }
  return c;
}

// ---- scenario files (render) ------------------------------------------------------

// A 0.1 s scenario at 40x30 whose wall shows the photo `file` (beside it,
// named at line 8).
std::string photo_scenario(const std::string& file) {
  return "duration_s: 0.1\n"
         "camera: {resolution: [40, 30], rate_hz: 60}\n"
         "trajectory:\n"
         "  segments:\n"
         "    - {type: straight, duration_s: 1, speed: 1}\n"
         "scene:\n"
         "  planes:\n"
         "    - {from: [-3, 2], to: [5, 2], z: [-1, 1], pattern: {type: photo, file: " + file + ", size_m: [2, 2], tiling: mirror}}\n";
}

#if LUMAVEL_CAMPAIGN_JPEG
// A w x h 8-bit gray baseline JPEG of a ramp (CMYK, each ink the ramp, with `cmyk`).
void write_jpeg(const std::string& path, int w, int h, bool cmyk = false) {
  std::FILE* f = std::fopen(path.c_str(), "wb");
  jpeg_compress_struct c{};
  jpeg_error_mgr e{};
  c.err = jpeg_std_error(&e);
  jpeg_create_compress(&c);
  jpeg_stdio_dest(&c, f);
  c.image_width = static_cast<JDIMENSION>(w);
  c.image_height = static_cast<JDIMENSION>(h);
  const int n = cmyk ? 4 : 1;
  c.input_components = n;
  c.in_color_space = cmyk ? JCS_CMYK : JCS_GRAYSCALE;
  jpeg_set_defaults(&c);
  jpeg_start_compress(&c, TRUE);
  std::vector<JSAMPLE> row(static_cast<size_t>(w * n));
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w * n; ++x) row[static_cast<size_t>(x)] = static_cast<JSAMPLE>((x / n * 7 + y * 13) ^ (x / n * y));
    JSAMPROW r = row.data();
    jpeg_write_scanlines(&c, &r, 1);
  }
  jpeg_finish_compress(&c);
  jpeg_destroy_compress(&c);
  std::fclose(f);
}
#endif

std::vector<Case> render_cases() {
  // 4 GB (sparse), render limited to 1 GB (was: "error: std::bad_alloc", naming nothing).
  std::vector<Case> c = {{"render: a 4 GB scenario", "render", [](const std::string& d) {
             write_text(d + "/scenario.yaml", "duration_s: 1\n");
             fs::resize_file(d + "/scenario.yaml", uintmax_t{4} << 30);
           }, Expect::kRefused, "scenario.yaml", "4294967296 bytes", {}, {}, {}, 1024}};
  // A header claiming 10^10 pixels in a few bytes, render limited to 1 GB
  // (was: 10 GB allocated, then "error: std::bad_alloc", naming nothing).
  c.push_back({"render: photo a PGM claiming 100000x100000", "render", [](const std::string& d) {
                 write_text(d + "/scenario.yaml", photo_scenario("photo.pgm"));
                 write_text(d + "/photo.pgm", "P5\n100000 100000\n255\n" + std::string(64, '\x80'));
               }, Expect::kRefused, "scenario.yaml:8: photo", "photo.pgm: PGM header: 100000x100000 pixels: each side must be 1..16384", {}, {}, {}, 1024});
  // 3e9 frame pairs (was: 25 s counting them past INT_MAX, then 'std::bad_alloc'; 1e10 hung).
  c.push_back({"render: 3e9 frame pairs", "render", [](const std::string& d) {
                 write_text(d + "/scenario.yaml", photo_scenario("photo.pgm"));
                 write_text(d + "/photo.pgm", "P5\n2 2\n255\n" + std::string(4, '\x80'));
                 replace_in(d + "/scenario.yaml", "duration_s: 0.1", "duration_s: 300000");
                 replace_in(d + "/scenario.yaml", "rate_hz: 60", "rate_hz: 10000");
               }, Expect::kRefused, "scenario.yaml", "camera rate_hz = 10000 Hz for duration_s = 300000 s is 3000000001 frame pairs", {}});
  // 4096x4096 frames, render limited to 200 MB: each of its 2 threads holds a
  // frame's radiance, 150 MB (was: "error: std::bad_alloc", naming nothing).
  c.push_back({"render: 4096x4096 frames in 200 MB", "render", [](const std::string& d) {
                 write_text(d + "/scenario.yaml", photo_scenario("photo.pgm"));
                 write_text(d + "/photo.pgm", "P5\n2 2\n255\n" + std::string(4, '\x80'));
                 replace_in(d + "/scenario.yaml", "resolution: [40, 30]", "resolution: [4096, 4096]");
               }, Expect::kRefused, "scenario.yaml", "out of memory rendering 4096x4096 frames with 2 threads", {}, {}, {}, 200});
  // More pixels than run bins (was: 8192x8192 rendered for 45 min, then refused by run's check).
  c.push_back({"render: 8192x8192 frames", "render", [](const std::string& d) {
                 write_text(d + "/scenario.yaml", photo_scenario("photo.pgm"));
                 write_text(d + "/photo.pgm", "P5\n2 2\n255\n" + std::string(4, '\x80'));
                 replace_in(d + "/scenario.yaml", "resolution: [40, 30]", "resolution: [8192, 8192]");
               }, Expect::kRefused, "scenario.yaml:2", "'resolution' = [8192, 8192] is 67108864 pixels", {}});
  // netpbm allows '#' comments in the header, and GIMP writes one (was:
  // refused, "photo.pgm: not a binary 8-bit PGM").
  c.push_back({"render: photo a PGM with a comment (as GIMP writes)", "render", [](const std::string& d) {
                 write_text(d + "/scenario.yaml", photo_scenario("photo.pgm"));
                 write_text(d + "/photo.pgm", "P5\n# CREATOR: GIMP PNM Filter Version 1.1\n2 2\n255\n" + std::string("\x10\x80\x40\xF0", 4));
               }, Expect::kSame, "", "", {}});
  // (was: "photo.pgm: not a binary 8-bit PGM", not saying what in it is not;
  // photos are read by the recording's PGM reader, with its words)
  c.push_back({"render: photo a 16-bit PGM", "render", [](const std::string& d) {
                 write_text(d + "/scenario.yaml", photo_scenario("photo.pgm"));
                 write_text(d + "/photo.pgm", "P5\n2 2\n65535\n" + std::string(8, '\x80'));
               }, Expect::kRefused, "scenario.yaml:8: photo", "photo.pgm: wrong depth: PGM maxval 65535, need 255 (8-bit)", {}});
#if LUMAVEL_CAMPAIGN_JPEG
  // 60000x16 pixels whose frame header (SOF0) says 60000 rows: 3.6 GB claimed.
  c.push_back({"render: photo a JPEG claiming 60000x60000", "render", [](const std::string& d) {
                 write_text(d + "/scenario.yaml", photo_scenario("photo.jpg"));
                 write_jpeg(d + "/photo.jpg", 60000, 16);
                 std::string b = read_text(d + "/photo.jpg");
                 const size_t sof = b.find("\xFF\xC0");
                 b[sof + 5] = static_cast<char>(60000 >> 8);
                 b[sof + 6] = static_cast<char>(60000 & 0xFF);
                 write_text(d + "/photo.jpg", b);
               }, Expect::kRefused, "scenario.yaml:8: photo", "photo.jpg: is 60000x60000", {}, {}, {}, 1024});
  // libjpeg converts no CMYK to gray: a valid print file was refused as
  // 'corrupt JPEG: Unsupported color conversion request'.
  c.push_back({"render: photo a CMYK JPEG", "render", [](const std::string& d) {
                 write_text(d + "/scenario.yaml", photo_scenario("photo.jpg"));
                 write_jpeg(d + "/photo.jpg", 64, 64, true);
               }, Expect::kRefused, "scenario.yaml:8: photo", "photo.jpg: a CMYK JPEG: photos are read from grayscale, RGB or YCbCr JPEGs", {}});
  // libjpeg's warning went to stderr and the missing part was decoded gray: exit 0.
  c.push_back({"render: photo a truncated JPEG", "render", [](const std::string& d) {
                 write_text(d + "/scenario.yaml", photo_scenario("photo.jpg"));
                 write_jpeg(d + "/photo.jpg", 256, 256);
                 truncate_file(d + "/photo.jpg", read_text(d + "/photo.jpg").size() / 2);
               }, Expect::kRefused, "scenario.yaml:8: photo", "photo.jpg: corrupt JPEG: Premature end of JPEG file", {}});
#endif
  return c;
}

// ---- running and judging -----------------------------------------------------------

struct Tools {
  std::string sim, read;
  double timeout_s = 60;
};

std::string one_line(std::string s) {
  for (char& ch : s)
    if (ch == '\n' || ch == '\r') ch = ' ';
  return s.size() > 220 ? s.substr(0, 220) + "..." : s;
}

// "" when the outcome is as the case expects, else the failure class.
std::string judge(const Case& k, const Outcome& o, const std::string& csv, const std::string& intact_csv) {
  if (o.signaled) return "crash (signal " + std::to_string(o.signal) + ")";
  if (o.timed_out) return "hang";
  if (o.err.find("Sanitizer") != std::string::npos || o.err.find("runtime error:") != std::string::npos)
    return "crash (sanitizer report)";
  const bool refused_clearly =
      o.code != 0 && o.err.find(k.file) != std::string::npos && o.err.find(k.where) != std::string::npos;
  switch (k.expect) {
    case Expect::kRefused:
      if (o.code == 0) return "silent (exit 0)";
      return refused_clearly ? "" : "unclear (wants '" + k.file + "' and '" + k.where + "')";
    case Expect::kFlagged:
      if (o.code != 0) return o.err.find("error: /") != std::string::npos ? "" : "unclear";
      return status_flags(csv) != 0 ? "" : "silent (no status flag)";
    case Expect::kSame:
      if (o.code != 0) return "refused a harmless variation";
      if (!intact_csv.empty() && read_text(csv) != read_text(intact_csv)) return "wrong (estimates differ)";
      return "";
  }
  return "?";
}

std::vector<std::string> command(const Tools& t, const Case& k, const std::string& arg, const std::string& work) {
  std::vector<std::string> options = k.options;
  for (std::string& o : options)
    if (o.rfind("@ARG", 0) == 0) o.replace(0, 4, arg);
  std::vector<std::string> a;
  if (k.tool == "run") a = {t.sim, "run", arg, "-q", "-o", work + "/out.csv", "--plot", work + "/plot.svg"};
  if (k.tool == "calibrate") a = {t.sim, "calibrate", arg, "-q"};
  if (!a.empty()) {
    a.insert(a.end(), options.begin(), options.end());
    return a;
  }
  if (k.tool == "import") return {t.sim, "import-slider", arg, work + "/imported", "--baseline", "0.02"};
  if (k.tool == "render") return {t.sim, "render", arg + "/scenario.yaml", work + "/rendered", "-q", "--force"};
  if (k.tool == "config") {
    a = {t.read, "config", "check", "--file", arg + "/rig.cfg"};
    a.insert(a.end(), options.begin(), options.end());
    return a;
  }
  a = {t.read, "replay", arg + "/run.hidrep"};  // its options, or -o to the work folder
  if (options.empty()) options = {"-o", work + "/out.csv"};
  a.insert(a.end(), options.begin(), options.end());
  return a;
}

}  // namespace

int main(int argc, char** argv) {
  Tools t;
  std::string base, keep;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string a = argv[i], v = argv[i + 1];
    if (a == "--sim") t.sim = v;
    else if (a == "--read") t.read = v;
    else if (a == "--base") base = v;
    else if (a == "--keep") keep = v;
    else if (a == "--timeout") t.timeout_s = std::stod(v);
    else {
      std::fprintf(stderr, "usage: cli_campaign --sim LUMAVEL_SIM --read LUMAVEL_READ [--base REC] [--keep DIR] [--timeout S]\n");
      return 2;
    }
  }
  if (!base.empty() && !fs::is_directory(base)) {
    std::fprintf(stderr, "cli_campaign: --base %s: not a recording folder\n", base.c_str());
    return 2;
  }
  if (t.sim.empty() || t.read.empty()) {
    std::fprintf(stderr, "cli_campaign: --sim and --read are needed\n");
    return 2;
  }
  t.sim = fs::absolute(t.sim).string();
  t.read = fs::absolute(t.read).string();
  fixture::TempDir tmp;
  const std::string root = keep.empty() ? tmp.path() : fs::absolute(keep).string();
  fs::create_directories(root);
  const std::string intact = root + "/intact", slider = root + "/slider_intact", work = root + "/work";
  fs::remove_all(intact);
  if (base.empty()) fixture::write_recording(intact);
  else fs::copy(base, intact, fs::copy_options::recursive);
  fs::remove_all(slider);
  write_slider(slider);
  fs::create_directories(work);

  // The intact answers, and a report file to damage.
  const std::string report = root + "/intact.hidrep", intact_csv = root + "/intact.csv", intact_import = root + "/intact_import.csv";
  Outcome o = run({t.sim, "run", intact, "-q", "-o", intact_csv, "--plot", work + "/plot.svg", "--hid", "file:" + report}, work, work + "/stdout.txt", t.timeout_s);
  if (o.code != 0) {
    std::fprintf(stderr, "cli_campaign: the intact recording does not run: %s\n", o.err.c_str());
    return 1;
  }
  fs::remove_all(work + "/imported");
  o = run({t.sim, "import-slider", slider, work + "/imported", "--baseline", "0.02"}, work, work + "/stdout.txt", t.timeout_s);
  if (o.code != 0 || run({t.sim, "run", work + "/imported", "-q", "-o", intact_import, "--plot", work + "/plot.svg"}, work, work + "/stdout.txt", t.timeout_s).code != 0) {
    std::fprintf(stderr, "cli_campaign: the intact slider dataset does not import: %s\n", o.err.c_str());
    return 1;
  }

  std::vector<Case> cases = recording_cases(intact);
  for (Case& k : slider_cases()) cases.push_back(std::move(k));
  for (Case& k : read_cases(report)) cases.push_back(std::move(k));
  for (Case& k : render_cases()) cases.push_back(std::move(k));

  int failures = 0, i = 0;
  for (const Case& k : cases) {
    const std::string copy = root + "/case" + std::to_string(i++);
    fs::remove_all(copy);
    if (k.tool == "run" || k.tool == "calibrate") fs::copy(intact, copy, fs::copy_options::recursive | fs::copy_options::copy_symlinks);
    else if (k.tool == "import") fs::copy(slider, copy, fs::copy_options::recursive);
    else fs::create_directories(copy);
    std::string judged;
    try {
      if (k.damage) k.damage(copy);
    } catch (const std::exception& e) {
      judged = std::string("the damage could not be made: ") + e.what();
    }
    const std::string arg = k.arg ? k.arg(copy) : copy;
    fs::remove_all(work + "/imported");
    fs::remove(work + "/out.csv");
    o = run(command(t, k, arg, work), work, k.stdout_to.empty() ? work + "/stdout.txt" : k.stdout_to, t.timeout_s,
            k.memory_mb);
    std::string csv = work + "/out.csv", reference = k.tool == "run" ? intact_csv : "";
    if (k.tool == "import" && o.code == 0) {  // judged by the estimates of what it wrote
      o = run({t.sim, "run", work + "/imported", "-q", "-o", csv, "--plot", work + "/plot.svg"}, work, work + "/stdout.txt", t.timeout_s);
      reference = intact_import;
    }
    if (judged.empty()) judged = judge(k, o, csv, reference);
    const char* expect = k.expect == Expect::kRefused ? "refused" : k.expect == Expect::kFlagged ? "flagged" : "same";
    std::printf("%-4s %-44s %-8s exit %-3d %s%s\n", judged.empty() ? "ok" : "FAIL", k.name.c_str(), expect, o.code,
                judged.empty() ? "" : ("[" + judged + "] ").c_str(), one_line(o.err).c_str());
    if (!judged.empty()) ++failures;
    if (keep.empty()) fs::remove_all(copy);
    if (fs::exists(copy + " with spaces")) fs::remove_all(copy + " with spaces");
  }
  std::printf("%zu cases, %d failed\n", cases.size(), failures);
  return failures == 0 ? 0 : 1;
}
