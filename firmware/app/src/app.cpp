#include "lumavel/app/app.hpp"

#include "lumavel/app/estimator_config.hpp"
#include "lumavel/protocol/descriptor.hpp"

namespace lumavel::app {
namespace {

using protocol::ConfigField;

uint16_t add_saturating(uint16_t a, uint32_t b) {
  const uint32_t s = a + b;
  return s > 0xFFFFu ? uint16_t{0xFFFF} : static_cast<uint16_t>(s);
}

// Firmware version, board name and the build's capacities, as DeviceInfo reports them.
protocol::DeviceInfo identity(const char* board_name) {
  protocol::DeviceInfo d{};
  d.fw_major = LUMAVEL_FW_MAJOR;
  d.fw_minor = LUMAVEL_FW_MINOR;
  d.fw_patch = LUMAVEL_FW_PATCH;
  for (size_t i = 0; i < protocol::kBoardNameSize && board_name[i] != '\0'; ++i) d.board[i] = board_name[i];
  d.max_columns = kMaxColumns;
  d.max_rows = kMaxRows;
  d.max_kernels = kMaxKernels;
  return d;
}

}  // namespace

App::App(const Hal& hal, const Board& board)
    : hal_(hal), board_(board), features_(identity(board.name), &hal.store, &App::apply_hook, this) {}

ConfigField App::apply_hook(void* ctx, const protocol::DeviceConfig& c, const EdgeOffsetQ15* const lens[2]) {
  return static_cast<App*>(ctx)->apply(c, lens);
}

// Called by the FeatureServer with a range-checked configuration and the
// lens tables it names (complete, CRC checked).
ConfigField App::apply(const protocol::DeviceConfig& c, const EdgeOffsetQ15* const lens[2]) {
  // The camera delivers one working resolution; the configuration must match it.
  if (c.width != hal_.camera.width()) return ConfigField::kWidth;
  if (c.height != hal_.camera.height()) return ConfigField::kHeight;
  EstimatorConfig e{};
  if (!to_estimator_config(c, e, lens)) {
    const ConfigField f = protocol::validate(c);
    return f != ConfigField::kOk ? f : ConfigField::kLens;
  }
  // The kernel bank copies the edges: the tables are not needed after this.
  const ConfigError err = estimator_.configure(e);
  if (err == ConfigError::kColumnEdges) return ConfigField::kLensEdges;
  if (err != ConfigError::kOk) return ConfigField::kEstimator;
  width_ = c.width;
  height_ = c.height;
  frame_period_us_ = c.frame_period_us;
  configured_ = true;
  have_frame_ = false;
  return ConfigField::kOk;
}

bool App::start() {
  hal_.watchdog.kick();
  features_.boot(board_.defaults);  // the stored configuration, else the defaults
  hal_.watchdog.kick();             // building the kernel tables takes a while
  return configured_;
}

void App::count_gap(uint64_t t_ns) {
  if (have_frame_ && t_ns > last_frame_ns_) {
    const uint64_t dt = t_ns - last_frame_ns_;
    static_assert(config::range<config::Quantity::kFramePeriod>.hi * 1000 <= 0xFFFFFFFFll, "a period in ns fits 32 bits");
    const uint32_t period = frame_period_us_ * 1000u;  // <= 1 s, fits 32 bits
    if (dt > uint64_t{period} + period / 2) {
      // Frames that should have arrived in between (32-bit division: no __aeabi_uldivmod).
      uint32_t missed = 0xFFFFu;  // a gap of over 4 s: saturate
      if (dt < 0xFFFFFFFFull - period) {
        const auto dt32 = static_cast<uint32_t>(dt);
        missed = (dt32 + period / 2) / period - 1u;
      }
      counters_.overruns = add_saturating(counters_.overruns, missed);
    }
  }
  have_frame_ = true;
  last_frame_ns_ = t_ns;
}

void App::push_gyro_until(uint64_t t_ns) {
  // Interpolation at t needs the first sample at or after t when there is one.
  if (have_gyro_ && last_gyro_ns_ >= t_ns) return;
  hal::GyroSample s{};
  while (hal_.gyro.read(s)) {
    estimator_.push_gyro(s.t_ns, s.rate_z);
    ++counters_.gyro_samples;
    have_gyro_ = true;
    last_gyro_ns_ = s.t_ns;
    if (s.t_ns >= t_ns) break;
  }
}

void App::send_measurement(const Estimate& e) {
  protocol::Measurement m{};
  m.seq = seq_++;
  m.t_ns = e.t_ns;
  m.frame_index = e.frame_index;
  m.v = e.v;
  m.distance = e.distance;
  m.heading = e.heading;
  m.status = e.status;
  m.overruns = counters_.overruns;
  m.gyro_offset = e.gyro_offset;
  uint8_t report[protocol::kMeasurementSize];
  const size_t n = protocol::encode_measurement(m, report, sizeof report);
  if (n == 0 || !hal_.link.send_input(report, n)) ++counters_.reports_dropped;
}

size_t App::handle_feature(uint8_t id, bool is_set, uint8_t* buf, size_t len, size_t cap) {
  ++counters_.feature_requests;
  if (is_set && id == protocol::kReportMailbox) {
    uint8_t wanted = 0, tag = 0;
    if (!protocol::decode_mailbox_request(buf, len, wanted, tag).ok()) return 0;
    mailbox_id_ = wanted;  // replaces a request not yet answered
    mailbox_tag_ = tag;
    return 1;
  }
  return FeatureServer::handle(&features_, id, is_set, buf, len, cap);
}

size_t App::feature_trampoline(void* ctx, uint8_t id, bool is_set, uint8_t* buf, size_t len,
                               size_t cap) {
  return static_cast<App*>(ctx)->handle_feature(id, is_set, buf, len, cap);
}

void App::send_mailbox() {
  if (mailbox_id_ == 0) return;
  uint8_t report[protocol::kMaxReportSize];
  const size_t n = FeatureServer::handle(&features_, mailbox_id_, false, report, sizeof report,
                                                  sizeof report);
  mailbox_id_ = 0;
  for (size_t i = 0; i < protocol::feature_chunk_count(n); ++i) {
    const protocol::FeatureChunk c = protocol::feature_chunk(report, n, mailbox_tag_, i);
    uint8_t chunk[protocol::kFeatureChunkSize];
    const size_t m = protocol::encode_feature_chunk(c, chunk, sizeof chunk);
    if (m == 0 || !hal_.link.send_input(chunk, m)) ++counters_.reports_dropped;
  }
}

RunState App::run_once() {
  if (!configured_) return RunState::kUnconfigured;
  hal_.watchdog.kick();
  hal::StereoImage img{0, {frame_[0], frame_[1]}, width_, height_};
  const hal::CaptureStatus st = hal_.camera.capture(img);
  if (st == hal::CaptureStatus::kEnd) return RunState::kEnd;
  RunState result = RunState::kSkipped;
  if (st == hal::CaptureStatus::kError) {
    ++counters_.capture_errors;
    counters_.overruns = add_saturating(counters_.overruns, 1);
  } else {
    const uint64_t t0 = hal_.clock.now_ns();
    count_gap(img.t_ns);
    push_gyro_until(img.t_ns);
    const FramePair pair{img.t_ns, {frame_[0], frame_[1]}, width_};
    send_measurement(estimator_.step(pair));
    ++counters_.frames;
    const uint64_t took = hal_.clock.now_ns() - t0;
    if (took > counters_.max_frame_ns) counters_.max_frame_ns = took;
    result = RunState::kFrame;
  }
  hal_.link.poll_features(&App::feature_trampoline, this);
  send_mailbox();
  return result;
}

void App::run() {
  for (;;) {
    const RunState s = run_once();
    if (s == RunState::kEnd || s == RunState::kUnconfigured) return;
  }
}

}  // namespace lumavel::app
