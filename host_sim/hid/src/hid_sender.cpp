#include "lumavel/host/hid_sender.hpp"

#include <cmath>
#include <cstring>
#include <thread>

#include "lumavel/core/limits.hpp"
#include "lumavel/units/si.hpp"

namespace lumavel::host {

namespace proto = lumavel::protocol;
using Clock = std::chrono::steady_clock;

namespace {

constexpr double kPi = 3.14159265358979323846;

proto::DeviceInfo sim_identity() {
  proto::DeviceInfo d{};
  d.fw_major = 0;
  d.fw_minor = 1;
  d.fw_patch = 0;
  std::strncpy(d.board, "lumavel-sim", proto::kBoardNameSize);
  d.max_columns = static_cast<uint16_t>(kMaxColumns);
  d.max_rows = static_cast<uint16_t>(kMaxRows);
  d.max_kernels = static_cast<uint8_t>(kMaxKernels);
  return d;
}

// The simulator's engine follows the recording, not the host: without a store
// only its own boot-time configuration is accepted and sets from the host are
// refused; with a store every validated set is accepted (the store keeps it,
// the engine does not change).
proto::ConfigField apply_own_only(void* ctx, const proto::DeviceConfig&, const EdgeOffsetQ15* const[2]) {
  return *static_cast<bool*>(ctx) ? proto::ConfigField::kOk : proto::ConfigField::kEstimator;
}

}  // namespace

proto::Measurement quantise_measurement(uint64_t t_ns, uint32_t frame_index, double v_mps,
                                        double distance_m, double heading_rad, uint16_t status,
                                        double gyro_offset_radps) {
  proto::Measurement m{};
  m.t_ns = t_ns;
  m.frame_index = frame_index;
  m.seq = static_cast<uint16_t>(frame_index);
  m.v = si::Speed::from_si(v_mps);
  m.gyro_offset = si::Rate::from_si(gyro_offset_radps);
  m.distance = si::Distance::from_si(distance_m);
  // The report's heading is wrapped into [-pi, pi) (AngleQ28).
  int64_t h = si::Angle::from_si(heading_rad);
  const int64_t pi_q = fx::kPiQ28;
  if (h >= pi_q || h < -pi_q) {
    h = si::to_q64(std::remainder(heading_rad, 2 * kPi), fx::kAngleFrac);
    if (h >= pi_q) h -= 2 * pi_q;
  }
  m.heading = static_cast<int32_t>(h);
  m.status = status;  // unknown bits are sent as they are: the host refuses them, visibly
  return m;
}

HidSender::HidSender(std::unique_ptr<hal::ReportLink> link, const HidSenderOptions& options,
                     std::unique_ptr<hal::ConfigStore> store)
    : link_(std::move(link)),
      opt_(options),
      store_(std::move(store)),
      features_(sim_identity(), store_.get(), apply_own_only, &accept_) {
  accept_ = true;
  features_.boot(proto::default_device_config());
  accept_ = store_ != nullptr;
}

void HidSender::set_resolution(uint16_t width, uint16_t height) {
  proto::DeviceConfig c = proto::defaults_for(width, height);  // 60 degrees, centre column
  accept_ = true;
  features_.boot(c);  // the stored configuration first; keeps the previous one if c is out of range
  accept_ = store_ != nullptr;
}

void HidSender::poll() { link_->poll_features(&app::FeatureServer::handle, &features_); }

bool HidSender::send(uint64_t t_ns, double v_mps, double distance_m, double heading_rad,
                     uint16_t status, double gyro_offset_radps) {
  proto::Measurement m = quantise_measurement(t_ns, frame_, v_mps, distance_m, heading_rad, status, gyro_offset_radps);
  m.overruns = overruns_;
  ++frame_;
  uint8_t buf[proto::kMeasurementSize];
  proto::encode_measurement(m, buf, sizeof buf);
  const auto next = last_ + std::chrono::microseconds(opt_.min_interval_us);
  while (Clock::now() < next) {
    poll();
    std::this_thread::sleep_for(std::chrono::microseconds(100));
  }
  const auto deadline = Clock::now() + std::chrono::milliseconds(sent_ == 0 ? opt_.first_wait_ms : opt_.wait_ms);
  for (;;) {
    poll();
    if (link_->send_input(buf, sizeof buf)) break;
    if (Clock::now() >= deadline) {
      if (overruns_ < 0xFFFF) ++overruns_;
      return false;
    }
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
  last_ = Clock::now();
  ++sent_;
  return true;
}

}  // namespace lumavel::host

namespace lumavel::host {

HidSenderOptions hid_sender_options_for(const std::string& spec) {
  HidSenderOptions o;
  if (spec.rfind("file:", 0) == 0) {
    o.min_interval_us = 0;
    o.first_wait_ms = 0;
    o.wait_ms = 0;
  }
  return o;
}

}  // namespace lumavel::host
