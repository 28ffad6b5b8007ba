#include "lumavel/host/render/recording_renderer.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

#include "lumavel/host/image_io.hpp"
#include "lumavel/host/recording_writer.hpp"
#include "lumavel/host/render/frame_renderer.hpp"
#include "lumavel/host/progress.hpp"
#include "lumavel/host/render/scene.hpp"
#include "lumavel/host/render/sensor_synthesis.hpp"

namespace lumavel::host::render {

RenderSummary render_recording(const Scenario& s, const std::string& out_dir,
                               const RenderOptions& opt) {
  const auto t0 = std::chrono::steady_clock::now();
  const Scene scene = build_scene(s);
  const FrameRenderer fr(s, scene);
  RecordingWriter writer(out_dir, camera_sensor(s, fr.rig(), 0), camera_sensor(s, fr.rig(), 1),
                         imu_sensor(s));
  RenderSummary sum;
  sum.frames = fr.frame_count();
  const std::vector<bool> drop = dropped_frames(s, sum.frames);
  std::vector<int> todo;
  for (int i = 0; i < sum.frames; ++i)
    if (!drop[static_cast<size_t>(i)]) todo.push_back(i);
  sum.dropped = sum.frames - static_cast<int>(todo.size());

  std::atomic<size_t> next{0};
  std::atomic<long> done{0};
  std::atomic<bool> failed{false};
  std::exception_ptr error;
  std::mutex mu;
  auto worker = [&] {
    std::vector<uint8_t> px;
    try {
      for (size_t k = next++; k < todo.size() && !failed; k = next++) {
        const int i = todo[k];
        const uint64_t t_ns = static_cast<uint64_t>(fr.frame_stamp_ns(i));
        for (int cam = 0; cam < 2; ++cam) {
          const FrameStats st = fr.render(i, cam, px);
          write_png_gray(writer.image_path(cam, t_ns), px.data(), fr.rig().pinhole().width,
                         fr.rig().pinhole().height);
          std::lock_guard<std::mutex> lock(mu);
          sum.max_subframes = std::max(sum.max_subframes, st.subframes);
          if (st.background_fraction > sum.max_background) {
            sum.max_background = st.background_fraction;
            sum.max_background_frame = i;
          }
        }
        ++done;
      }
    } catch (...) {
      std::lock_guard<std::mutex> lock(mu);
      if (!error) error = std::current_exception();
      failed = true;
    }
  };
  cli::Progress bar(static_cast<long>(todo.size()), "render");
  std::vector<std::thread> pool;
  const int n_threads = std::max(1, opt.threads);
  for (int k = 0; k < n_threads; ++k) pool.emplace_back(worker);
  while (opt.progress && done < static_cast<long>(todo.size()) && !failed) {
    bar.update(done);
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  for (auto& t : pool) t.join();
  if (error) std::rethrow_exception(error);
  if (opt.progress) bar.finish();

  for (int i : todo) writer.add_frame_pair_written(static_cast<uint64_t>(fr.frame_stamp_ns(i)));
  const auto imu = synthesize_imu(s, fr.trajectory());
  for (const auto& m : imu) writer.add_imu(m.t_ns, m.w, m.a);
  const auto gt = synthesize_groundtruth(s, fr.trajectory());
  for (const auto& g : gt) writer.add_groundtruth(g);
  writer.finish();
  sum.imu_samples = imu.size();
  sum.groundtruth_samples = gt.size();
  sum.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return sum;
}

}  // namespace lumavel::host::render
