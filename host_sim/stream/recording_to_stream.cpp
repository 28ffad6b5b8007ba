// Converts a recording (EuRoC/ASL layout, host_sim/recording) into the compact
// stream the stream boards read (boards/common/stream/.../format.hpp): frames
// binned to the working resolution like a board driver bins its sensor, and the
// body yaw rate as RateQ24, in time order (each frame after the gyro samples up
// to its time, so a firmware reading the stream sees them as a sensor would).
//   lumavel_recording_to_stream <recording dir> <out.lvs> <width> <height>
#include <cstdio>
#include <exception>
#include <vector>

#include "lumavel/host/file_camera.hpp"
#include "lumavel/host/file_gyro.hpp"
#include "lumavel/host/output_file.hpp"
#include "lumavel/host/path_check.hpp"
#include "lumavel/host/recording.hpp"
#include "lumavel/host/recording_error.hpp"
#include "lumavel/host/rig.hpp"
#include "lumavel/stream/format.hpp"
#include "lumavel/stream/stream_writer.hpp"
#include "lumavel/stream/tool_args.hpp"

// Exit status as lumavel-sim's: 0 done, 1 bad input or failure, 2 usage error.
int main(int argc, char** argv) {
  if (argc != 5) {
    std::fprintf(stderr, "usage: %s <recording dir> <out.lvs> <width> <height>\n", argv[0]);
    return 2;
  }
  long long width = 0, height = 0;
  if (!lumavel::stream::path_argument(argv[0], "recording dir", argv[1]) ||
      !lumavel::stream::path_argument(argv[0], "out.lvs", argv[2]) ||
      !lumavel::stream::whole_argument(argv[0], "width", argv[3], 16, 2048, width) ||
      !lumavel::stream::whole_argument(argv[0], "height", argv[4], 1, 2048, height))
    return 2;
  if (!lumavel::stream::output_argument(argv[0], "out.lvs", argv[2])) return 1;
  const int w = static_cast<int>(width);
  const int h = static_cast<int>(height);
  try {
    const lumavel::host::Recording rec = lumavel::host::load_recording(argv[1]);
    // The stream written over a file the recording holds (its data.csv, a
    // frame) destroyed it, exit 0: refused as lumavel-sim run refuses it.
    if (lumavel::host::overwrites_recording(rec, argv[2])) {
      std::fprintf(stderr, "%s: %s (out.lvs): that is part of the recording being read (%s); write the stream elsewhere\n",
                   argv[0], lumavel::host::shown_path(argv[2]).c_str(), lumavel::host::shown_path(rec.root).c_str());
      return 2;
    }
    // Its hint names this tool's arguments (was: '--width/--height', which it has not).
    lumavel::host::check_bins_down(rec, {w, h}, "<width> <height>");
    lumavel::host::FileStereoCamera camera(rec, w, h);
    lumavel::host::FileGyro gyro(rec);
    // Written aside and moved into place once whole (OutputFile): a frame
    // that failed to decode left the pairs before it as OUT.lvs, a shorter
    // stream that lumavel_app_host ran, exit 0; a write error is said with
    // its reason (was: 'cannot open for writing', 'write failed').
    lumavel::host::OutputFile out(argv[2], "the stream");
    lumavel::stream::StreamWriter o{out.get()};
    o.header(w, h);
    std::vector<uint8_t> px[2];
    px[0].resize(static_cast<size_t>(w) * static_cast<size_t>(h));
    px[1].resize(px[0].size());
    lumavel::hal::StereoImage img{0, {px[0].data(), px[1].data()}, static_cast<uint16_t>(w),
                                  static_cast<uint16_t>(h)};
    size_t frames = 0, samples = 0;
    // One sample read ahead: the first one after the frames written so far.
    lumavel::hal::GyroSample next{};
    bool have_next = gyro.read(next);
    for (;;) {
      const lumavel::hal::CaptureStatus st = camera.capture(img);
      if (st == lumavel::hal::CaptureStatus::kEnd) break;
      if (st == lumavel::hal::CaptureStatus::kError) {
        std::fprintf(stderr, "%s\n", camera.error().c_str());
        return 1;  // the stream left unwritten (out's destructor)
      }
      while (have_next && next.t_ns <= img.t_ns) {
        o.gyro(next.t_ns, next.rate_z);
        ++samples;
        have_next = gyro.read(next);
      }
      o.u8(lumavel::stream::kTagFrame);
      o.u64(img.t_ns);
      o.bytes(px[0].data(), px[0].size());
      o.bytes(px[1].data(), px[1].size());
      ++frames;
    }
    if (have_next) {  // the first sample after the last frame: interpolation needs it
      o.gyro(next.t_ns, next.rate_z);
      ++samples;
    }
    out.commit();
    std::fprintf(stderr, "%s: %zu frames at %dx%d, %zu gyro samples\n", lumavel::host::shown_path(argv[2]).c_str(),
                 frames, w, h, samples);
    return 0;
  } catch (const std::exception& e) {  // RecordingError names file and line/frame
    std::fprintf(stderr, "%s\n", e.what());
    return 1;
  }
}
