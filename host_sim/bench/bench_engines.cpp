// Compute time per frame of lumavel's two engines and of the keypoint
// stereo VO on the same recordings, each fed the binned frames `run` feeds it.
// Frames are decoded and binned first, so only the engine is timed (push_gyro and
// step, one thread): wall clock, the best of the repeats (the run least
// disturbed by other load on a shared machine), and the thread's CPU time.
// Prints a table; figures, never a test.
//   lumavel-bench-engines [--size WxH]... [--repeat N] REC...
#include <time.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "lumavel/host/decimal_text.hpp"
#include "lumavel/host/file_camera.hpp"
#include "lumavel/host/groundtruth.hpp"
#include "lumavel/host/path_check.hpp"
#include "lumavel/host/recording.hpp"
#include "lumavel/host/run_metrics.hpp"
#include "lumavel/host/run_recording.hpp"

using namespace lumavel::host;

namespace {

struct Frames {
  std::vector<std::vector<uint8_t>> cam[2];
  std::vector<uint64_t> t;
  std::vector<size_t> gyro_end;  // imu samples pushed before frame i: [0, gyro_end[i])
};

// What `run --engine KIND --width W --height H` runs with, the rest by default.
RunOptions run_options(EngineKind kind, int w, int h) {
  RunOptions o;
  o.engine = kind;
  o.size = {w, h};
  return o;
}

// Decoded, processed and binned as run_recording does for `kind` (the clip
// ceiling; undistorted for lumavel's engines where the lens asks for it),
// gyro samples split the same way.
Frames load_frames(const Recording& rec, EngineKind kind, int w, int h) {
  Frames f;
  FileStereoCamera camera(rec, w, h, 2, 16, frame_processing(rec, run_options(kind, w, h)));
  const size_t n = static_cast<size_t>(w) * static_cast<size_t>(h);
  std::vector<uint8_t> b0(n), b1(n);
  lumavel::hal::StereoImage img{0, {b0.data(), b1.data()}, 0, 0};
  size_t gyro = 0;
  for (;;) {
    const lumavel::hal::CaptureStatus st = camera.capture(img);
    if (st == lumavel::hal::CaptureStatus::kEnd) break;
    if (st == lumavel::hal::CaptureStatus::kError) throw RecordingError(camera.error());
    gyro = gyro_samples_through(rec, gyro, img.t_ns);
    f.cam[0].push_back(b0);
    f.cam[1].push_back(b1);
    f.t.push_back(img.t_ns);
    f.gyro_end.push_back(gyro);
  }
  return f;
}

struct Timing {
  double us_per_frame = 0;  // wall clock, best of the repeats
  double cpu_us_per_frame = 0;  // this thread's CPU time, best of the repeats
  double e_percent = -1;    // E of the run, -1 without ground truth
};

double thread_cpu_s() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

Timing time_engine(const Recording& rec, const Frames& f, EngineKind kind, int w, int h, int repeat) {
  const RunOptions o = run_options(kind, w, h);
  const EstimatorSettings s = run_settings(rec, o);
  std::vector<double> us, cpu_us;
  std::vector<TrackPoint> track;
  for (int r = 0; r < repeat; ++r) {
    std::unique_ptr<Engine> e = make_run_engine(rec, o, s);
    track.clear();
    size_t gyro = 0;
    const auto t0 = std::chrono::steady_clock::now();
    const double c0 = thread_cpu_s();
    for (size_t i = 0; i < f.t.size(); ++i) {
      for (; gyro < f.gyro_end[i]; ++gyro) e->push_gyro(rec.imu_samples[gyro].t_ns, body_yaw_rate(rec.imu, rec.imu_samples[gyro]));
      const EngineEstimate est = e->step(f.t[i], f.cam[0][i].data(), f.cam[1][i].data());
      track.push_back(TrackPoint{f.t[i], est.v, 0, est.status});
    }
    const double s_total = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const double n = static_cast<double>(std::max<size_t>(1, f.t.size()));
    us.push_back(1e6 * s_total / n);
    cpu_us.push_back(1e6 * (thread_cpu_s() - c0) / n);
  }
  Timing out;
  out.us_per_frame = *std::min_element(us.begin(), us.end());
  out.cpu_us_per_frame = *std::min_element(cpu_us.begin(), cpu_us.end());
  if (!rec.groundtruth.empty()) {
    std::vector<uint64_t> t(f.t);
    const std::vector<double> v = true_forward_velocity(rec.groundtruth, t);
    for (size_t i = 0; i < track.size(); ++i) track[i].v_true = v[i];
    out.e_percent = compute_metrics(track).e_percent;
  }
  return out;
}

std::string name_of(std::string path) {
  while (path.size() > 1 && path.back() == '/') path.pop_back();
  const size_t s = path.find_last_of('/');
  std::string n = s == std::string::npos ? path : path.substr(s + 1);
  if (n == "mav0" && s != std::string::npos) return name_of(path.substr(0, s));
  return n;
}

// `why` (a refused option, "" for none) first, then the usage: exit 2.
int usage(const std::string& why = "") {
  if (!why.empty()) std::fprintf(stderr, "lumavel-bench-engines: %s\n", why.c_str());
  std::fputs("usage: lumavel-bench-engines [--size WxH]... [--repeat N] REC...\n"
             "  compute time per frame (one thread; wall clock and CPU time, best of the repeats) of the\n"
             "  fixed, float and vo engines on each recording at each working size (default 40x30, 80x60,\n"
             "  160x120; --repeat 3)\n",
             stderr);
  return 2;
}

// --size and --repeat are read whole, as lumavel-sim's options are
// (decimal_text.hpp): sscanf took "40x30junk" as 40x30 and atoi "1e3"
// repeats as 1, the figures of another run than asked, exit 0.
bool whole_in(const std::string& text, long long lo, long long hi, long long& out) {
  const WholeText w = read_whole(text);
  if (w.problem != WholeText::Problem::kNone || w.value < lo || w.value > hi) return false;
  out = w.value;
  return true;
}

bool read_size(const std::string& text, int& w, int& h) {
  const size_t x = text.find('x');
  long long a = 0, b = 0;
  if (x == std::string::npos || !whole_in(text.substr(0, x), 1, 2048, a) || !whole_in(text.substr(x + 1), 1, 2048, b))
    return false;
  w = static_cast<int>(a);
  h = static_cast<int>(b);
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::pair<int, int>> sizes;
  std::vector<std::string> recs;
  int repeat = 3;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--size" && i + 1 < argc) {
      int w = 0, h = 0;
      if (!read_size(argv[++i], w, h))
        return usage("--size: must be WxH with W and H whole numbers in 1..2048, not '" + shown_path(argv[i]) + "'");
      sizes.emplace_back(w, h);
    } else if (a == "--repeat" && i + 1 < argc) {
      long long n = 0;
      if (!whole_in(argv[++i], 1, 1000, n))
        return usage("--repeat: must be a whole number in 1..1000, not '" + shown_path(argv[i]) + "'");
      repeat = static_cast<int>(n);
    } else if (a.empty() || a[0] == '-') {
      return usage();
    } else {
      recs.push_back(a);
    }
  }
  if (recs.empty()) return usage();
  if (sizes.empty()) sizes = {{40, 30}, {80, 60}, {160, 120}};
  std::printf("| recording | working | frames | fixed us/frame | float us/frame | vo us/frame | vo / fixed | vo / fixed, CPU time | E fixed | E vo |\n"
              "|---|---|---|---|---|---|---|---|---|---|\n");
  try {
    for (const std::string& path : recs) {
      const Recording rec = load_recording(path);
      for (const auto& [w, h] : sizes) {
        if (w > rec.cam[0].width || h > rec.cam[0].height) {  // said, not a row left out unsaid
          std::fprintf(stderr, "lumavel-bench-engines: %s: %dx%d skipped: larger than its %dx%d sensor\n",
                       shown_path(path).c_str(), w, h, rec.cam[0].width, rec.cam[0].height);
          continue;
        }
        const Frames f = load_frames(rec, EngineKind::kFixed, w, h);
        const Timing fx = time_engine(rec, f, EngineKind::kFixed, w, h, repeat);
        const Timing fl = time_engine(rec, f, EngineKind::kFloat, w, h, repeat);
        const Timing vo = time_engine(rec, load_frames(rec, EngineKind::kVo, w, h), EngineKind::kVo, w, h, repeat);
        char e[64] = "- | -";
        if (fx.e_percent >= 0) std::snprintf(e, sizeof e, "%.2f %% | %.2f %%", fx.e_percent, vo.e_percent);
        std::printf("| %s | %dx%d | %zu | %.1f | %.1f | %.0f | %.0f | %.0f | %s |\n", name_of(path).c_str(), w, h,
                    f.t.size(), fx.us_per_frame, fl.us_per_frame, vo.us_per_frame, vo.us_per_frame / fx.us_per_frame,
                    vo.cpu_us_per_frame / fx.cpu_us_per_frame, e);
        std::fflush(stdout);
      }
    }
  } catch (const std::exception& ex) {
    std::fprintf(stderr, "lumavel-bench-engines: %s\n", ex.what());
    return 1;
  }
  return 0;
}
