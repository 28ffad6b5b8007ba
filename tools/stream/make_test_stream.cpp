// Writes a synthetic recorded stream (boards/common/stream format): a vehicle
// driving past a textured wall 1 m to its left at a varying speed, swaying in
// yaw, seen by two cameras 8 cm apart, with a 500 Hz gyro. On the way the host
// reads the device info and configuration, sets a new configuration, sends a
// corrupt one, asks for the configuration through the mailbox, and three
// frames are missing (an overrun). Deterministic for a given seed.
// With --lens, both cameras see the wall through barrel lenses
// (barrel_lens.hpp) and, at 7/10 of the frames (after every read-back, so
// that only the estimates can tell the modes apart), the host uploads lens
// tables and a configuration naming them, then gets the device info:
// `barrel` tables that describe the lenses, or `flat` ones (all zero: a
// pinhole, what a device that ignored the tables would run).
//   lumavel_make_test_stream <out.lvs> <width> <height> <frames> [seed] [--lens barrel|flat]
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "lumavel/app/estimator_config.hpp"
#include "lumavel/host/output_file.hpp"
#include "lumavel/protocol/descriptor.hpp"
#include "lumavel/protocol/device_config.hpp"
#include "lumavel/protocol/reports.hpp"
#include "lumavel/stream/format.hpp"
#include "lumavel/units/si.hpp"
#include "lumavel/stream/run_stream.hpp"
#include "lumavel/stream/stream_writer.hpp"
#include "lumavel/stream/tool_args.hpp"
#include "barrel_lens.hpp"

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kWall = 1.0;       // m, wall distance on the left
constexpr double kBaseline = 0.08;  // m
constexpr double kFramePeriod = 1.0 / 60;
constexpr double kGyroPeriod = 0.002;


double distance(double t) { return 1.5 * t + 0.5 * (1 - std::cos(2 * kPi * 0.3 * t)) / (2 * kPi * 0.3); }
double heading(double t) { return 0.05 * std::sin(2 * kPi * 0.5 * t); }
double yaw_rate(double t) { return 0.05 * 2 * kPi * 0.5 * std::cos(2 * kPi * 0.5 * t); }
double texture(double x) {
  return 128 + 60 * std::sin(2 * kPi * x / 0.37 + 1) + 40 * std::sin(2 * kPi * x / 0.13 + 2) +
         20 * std::sin(2 * kPi * x / 0.051);
}

// k1: the camera's radial distortion (0: pinhole).
void render(double t, double cam_x, double k1, int w, int h, uint32_t& rng, uint8_t* px) {
  const double th = heading(t);
  const double fu = 34.64 * w / 40.0;
  const double cu = (w - 1) / 2.0;
  const double cx = distance(t) + cam_x * std::cos(th);
  const double cy = cam_x * std::sin(th);
  for (int u = 0; u < w; ++u) {
    const double x_u = k1 == 0 ? (u - cu) / fu : lumavel::stream::undistort((u - cu) / fu, k1);
    const double dir = th + kPi / 2 - std::atan(x_u);  // looking left, upright
    const double r = (kWall - cy) / std::sin(dir);
    const double x = cx + r * std::cos(dir);
    for (int v = 0; v < h; ++v) {
      rng = rng * 1664525u + 1013904223u;
      const double noise = static_cast<double>(rng >> 29) - 3.5;  // +-3.5 grey levels
      const double g = texture(x) * (1.0 - 0.003 * (v - h / 2.0)) + noise;
      px[v * w + u] = static_cast<uint8_t>(std::lround(std::fmin(255.0, std::fmax(0.0, g))));
    }
  }
}

void set_feature(lumavel::stream::StreamWriter& o, const uint8_t* report, size_t n) {
  o.u8(lumavel::stream::kTagSetFeature);
  o.u8(report[0]);
  o.u8(static_cast<uint8_t>(n));
  o.bytes(report, n);
}

void get_feature(lumavel::stream::StreamWriter& o, uint8_t id) {
  o.u8(lumavel::stream::kTagGetFeature);
  o.u8(id);
}

enum class Lens { kNone, kBarrel, kFlat };

// The lens sets (barrel_lens.hpp) for a w x h stream: tables of the device's
// pinhole geometry in the configuration it will run.
std::vector<std::vector<uint8_t>> lens_sets(Lens lens, int w, int h) {
  lumavel::protocol::DeviceConfig c = lumavel::stream::defaults_for(static_cast<uint16_t>(w), static_cast<uint16_t>(h));
  c.tau_us = 250000;
  lumavel::EstimatorConfig geometry{};
  if (!lumavel::app::to_estimator_config(c, geometry)) std::abort();
  std::vector<lumavel::EdgeOffsetQ15> tables[2];
  for (int i = 0; i < 2; ++i) {
    tables[i] = lens == Lens::kBarrel
                    ? lumavel::stream::barrel_edge_offsets(geometry.cam[i], c.width, lumavel::stream::kBarrelK1[i])
                    : std::vector<lumavel::EdgeOffsetQ15>(static_cast<size_t>(w) + 1, 0);
  }
  return lumavel::stream::lens_upload_reports(c, tables);
}

}  // namespace

// Exit status as lumavel-sim's: 0 done, 1 failure, 2 usage error.
int main(int argc, char** argv) {
  Lens lens = Lens::kNone;
  if (argc >= 7 && std::string(argv[argc - 2]) == "--lens") {
    const std::string mode = argv[argc - 1];
    lens = mode == "barrel" ? Lens::kBarrel : mode == "flat" ? Lens::kFlat : Lens::kNone;
    if (lens == Lens::kNone) {
      std::fprintf(stderr, "%s: --lens takes barrel or flat, not '%s'\n", argv[0], mode.c_str());
      return 2;
    }
    argc -= 2;
  }
  if (argc < 5 || argc > 6) {
    std::fprintf(stderr, "usage: %s <out.lvs> <width> <height> <frames> [seed] [--lens barrel|flat]\n", argv[0]);
    return 2;
  }
  // At most 10^6 frames: 4.6 hours at 60 Hz (frames * 7 stays within an int).
  long long width = 0, height = 0, frame_count = 0, seed = 1;
  if (!lumavel::stream::path_argument(argv[0], "out.lvs", argv[1]) ||
      !lumavel::stream::whole_argument(argv[0], "width", argv[2], 16, 2048, width) ||
      !lumavel::stream::whole_argument(argv[0], "height", argv[3], 1, 2048, height) ||
      !lumavel::stream::whole_argument(argv[0], "frames", argv[4], 1, 1000000, frame_count) ||
      (argc == 6 && !lumavel::stream::whole_argument(argv[0], "seed", argv[5], 0, UINT32_MAX, seed)))
    return 2;
  if (!lumavel::stream::output_argument(argv[0], "out.lvs", argv[1])) return 1;
  const int w = static_cast<int>(width);
  const int h = static_cast<int>(height);
  const int frames = static_cast<int>(frame_count);
  uint32_t rng = static_cast<uint32_t>(seed);
  if (lens != Lens::kNone && w + 1 > 255) {  // report 0x05 numbers edges with one byte
    std::fprintf(stderr, "%s: --lens needs width <= 254\n", argv[0]);
    return 2;
  }
  // Written aside and moved into place once whole (OutputFile): a stream too
  // short for its lens upload was refused, exit 1, but left behind without
  // it; a write error is said with its reason (was: 'cannot open for
  // writing', 'write failed').
  std::unique_ptr<lumavel::host::OutputFile> out;
  try {
    out = std::make_unique<lumavel::host::OutputFile>(argv[1], "the stream");
  } catch (const std::runtime_error& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 1;
  }
  lumavel::stream::StreamWriter o{out->get()};
  o.header(w, h);

  std::vector<uint8_t> px(static_cast<size_t>(w) * static_cast<size_t>(h));
  const double k1[2] = {lens == Lens::kNone ? 0.0 : lumavel::stream::kBarrelK1[0],
                        lens == Lens::kNone ? 0.0 : lumavel::stream::kBarrelK1[1]};
  std::vector<std::vector<uint8_t>> pending;  // lens sets still to send
  size_t next_set = 0;
  int gyro_k = 0;
  for (int k = 0; k < frames; ++k) {
    const double t = 0.1 + k * kFramePeriod;
    for (; gyro_k * kGyroPeriod <= t; ++gyro_k) {
      const double tg = gyro_k * kGyroPeriod;
      o.gyro(static_cast<uint64_t>(std::llround(tg * 1e9)), lumavel::si::Rate::from_si(yaw_rate(tg)));
    }
    if (k == frames * 3 / 10) {
      get_feature(o, lumavel::protocol::kReportDeviceInfo);
      get_feature(o, lumavel::protocol::kReportConfig);
    }
    if (k == frames / 2) {
      lumavel::protocol::DeviceConfig c = lumavel::stream::defaults_for(static_cast<uint16_t>(w), static_cast<uint16_t>(h));
      c.tau_us = 250000;
      uint8_t report[lumavel::protocol::kConfigSize];
      const size_t n = lumavel::protocol::encode_config(c, report, sizeof report);
      set_feature(o, report, n);
      report[20] ^= 0x40;  // corrupt: the device must refuse it (CRC)
      set_feature(o, report, n);
      uint8_t mailbox[lumavel::protocol::kMailboxSize];
      const size_t m = lumavel::protocol::encode_mailbox_request(lumavel::protocol::kReportConfig, 0x5A, mailbox, sizeof mailbox);
      set_feature(o, mailbox, m);
      get_feature(o, lumavel::protocol::kReportDeviceInfo);
    }
    if (lens != Lens::kNone && k == frames * 7 / 10) pending = lens_sets(lens, w, h);
    // The device serves at most StreamReader::kRequestQueue requests per
    // frame: 3 sets per frame, then the info get after the last one.
    for (int n = 0; n < 3 && next_set < pending.size(); ++n, ++next_set) {
      set_feature(o, pending[next_set].data(), pending[next_set].size());
      if (next_set + 1 == pending.size()) get_feature(o, lumavel::protocol::kReportDeviceInfo);
    }
    const bool dropped = k >= frames * 6 / 10 && k < frames * 6 / 10 + 3;
    if (dropped) continue;
    o.u8(lumavel::stream::kTagFrame);
    o.u64(static_cast<uint64_t>(std::llround(t * 1e9)));
    render(t, 0.0, k1[0], w, h, rng, px.data());
    o.bytes(px.data(), px.size());
    render(t, kBaseline, k1[1], w, h, rng, px.data());
    o.bytes(px.data(), px.size());
  }
  if (next_set < pending.size() || (lens != Lens::kNone && pending.empty())) {
    std::fprintf(stderr, "%s: %d frames are too few to upload the lens\n", argv[0], frames);
    return 1;  // the stream left unwritten (out's destructor)
  }
  try {
    out->commit();
  } catch (const std::runtime_error& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 1;
  }
  return 0;
}
