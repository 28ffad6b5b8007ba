// Throughput of `lumavel-sim run` (decode + bin + engine + CSV) on generated
// PNG recordings at 40x30 and 640x480 sensor resolution. Prints frames/s.
//   bench_run [--frames-small N] [--frames-large N] [--engine fixed|float] [--keep DIR]
#include <unistd.h>

#include <chrono>
#include <ctime>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include "lumavel/host/file_camera.hpp"
#include "lumavel/host/recording_writer.hpp"
#include "lumavel/host/run_recording.hpp"

using namespace lumavel::host;

namespace {

// A textured wall seen sideways, moving at 1 m/s: a smooth random-looking
// profile along u, shifted a little each frame, with mild vertical shading.
void make_recording(const std::string& dir, int w, int h, int frames) {
  CameraSensor cam;
  cam.rate_hz = 100;
  cam.width = w;
  cam.height = h;
  cam.fu = cam.fv = 0.8 * w;
  cam.cu = 0.5 * w - 0.5;
  cam.cv = 0.5 * h - 0.5;
  cam.distortion = {0, 0, 0, 0};
  // Looking left (+y), upright: camera x = body x, camera y = -body z, z = body y.
  CameraSensor cam0 = cam, cam1 = cam;
  const lumavel::host::Pose look_left = {1, 0, 0, -0.04, 0, 0, 1, 0, 0, -1, 0, 0, 0, 0, 0, 1};
  cam0.T_BS = look_left;
  cam1.T_BS = look_left;
  cam1.T_BS[3] = 0.04;
  ImuSensor imu;
  imu.rate_hz = 500;
  RecordingWriter writer(dir, cam0, cam1, imu);
  std::vector<uint8_t> a(static_cast<size_t>(w) * static_cast<size_t>(h)), b(a.size());
  auto fill = [&](std::vector<uint8_t>& img, double shift_px) {
    for (int u = 0; u < w; ++u) {
      const double x = (u + shift_px) * 40.0 / w;
      const double p = 128 + 50 * std::sin(0.9 * x) + 30 * std::sin(2.3 * x + 1) + 15 * std::sin(5.1 * x + 2);
      for (int v = 0; v < h; ++v)
        img[static_cast<size_t>(v * w + u)] = static_cast<uint8_t>(std::lround(p * (0.8 + 0.2 * v / h)));
    }
  };
  const uint64_t t0 = 1000000000ull, dt = 10000000ull;
  for (int i = 0; i < frames; ++i) {
    fill(a, 0.3 * i);
    fill(b, 0.3 * i + 0.3 * w / 40.0);
    writer.add_frame_pair(t0 + static_cast<uint64_t>(i) * dt, a.data(), b.data());
  }
  const double wz[3] = {0, 0, 0.01}, acc[3] = {0, 0, 9.81};
  for (uint64_t t = t0 - dt; t <= t0 + static_cast<uint64_t>(frames + 1) * dt; t += 2000000ull) writer.add_imu(t, wz, acc);
  writer.finish();
}

void bench(const std::string& root, int w, int h, int frames, EngineKind engine) {
  const std::string dir = root + "/rec_" + std::to_string(w) + "x" + std::to_string(h);
  make_recording(dir, w, h, frames);
  const Recording rec = load_recording(dir);

  // Wall time gives frames/s; process CPU time (all threads) per pair shows
  // the cost independently of other load on the machine.
  auto report = [&](const char* what, size_t n, double wall_s, double cpu_s) {
    std::printf("%4dx%-4d PNG  %-28s: %6zu pairs in %6.3f s = %8.0f pairs/s  (CPU %.3f ms/pair)\n", w, h, what, n,
                wall_s, static_cast<double>(n) / wall_s, 1e3 * cpu_s / static_cast<double>(n));
  };
  // Decode + bin only (the file camera), to separate I/O from the engine.
  {
    FileStereoCamera cam(rec, 40, 30);
    std::vector<uint8_t> b0(1200), b1(1200);
    lumavel::hal::StereoImage img{0, {b0.data(), b1.data()}, 0, 0};
    const std::clock_t c0 = std::clock();
    const auto start = std::chrono::steady_clock::now();
    size_t n = 0;
    while (cam.capture(img) == lumavel::hal::CaptureStatus::kOk) ++n;
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    report("decode+bin to 40x30 only", n, s, static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC);
  }
  std::FILE* sink = std::fopen("/dev/null", "w");
  RunOptions opt;
  opt.engine = engine;
  const std::clock_t c0 = std::clock();
  const auto start = std::chrono::steady_clock::now();
  const RunResult r = run_recording(rec, opt, sink);
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::fclose(sink);
  const std::string what = std::string("run, ") + engine_name(engine) + " engine, 40x30";
  report(what.c_str(), r.frames, s, static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC);
}

}  // namespace

int main(int argc, char** argv) {
  int small = 6000, large = 1000;
  std::string engine = "fixed", keep;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--frames-small")) small = std::atoi(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--frames-large")) large = std::atoi(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--engine")) engine = argv[i + 1];
    else if (!std::strcmp(argv[i], "--keep")) keep = argv[i + 1];
  }
  std::string root = keep;
  if (root.empty()) {
    char tmpl[] = "/tmp/lumavel_bench_XXXXXX";
    if (!::mkdtemp(tmpl)) return 1;
    root = tmpl;
  }
  try {
    const EngineKind kind = parse_engine_kind(engine);
    std::printf("lumavel-sim run throughput (%u hardware threads, 2 decode threads)\n",
                std::thread::hardware_concurrency());
    bench(root, 40, 30, small, kind);
    bench(root, 640, 480, large, kind);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_run: %s\n", e.what());
    return 1;
  }
  if (keep.empty()) std::filesystem::remove_all(root);
  return 0;
}
