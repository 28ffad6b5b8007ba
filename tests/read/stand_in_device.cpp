#include "stand_in_device.hpp"

#include <cstring>

#include "lumavel/protocol/descriptor.hpp"
#include "lumavel/protocol/device_config.hpp"

namespace lumavel::test {

namespace {

constexpr uint64_t kPeriodNs = 16667000;  // the default configuration's frame period
StandInDevice* g_device = nullptr;
int g_handle = 0;  // what open_path hands out

hid_device* handle() { return reinterpret_cast<hid_device*>(&g_handle); }

}  // namespace

StandInDevice::StandInDevice() {
  for (uint64_t k = 1; k <= 20000; ++k) camera_.times.push_back(k * kPeriodNs);
  for (uint64_t k = 0; k <= 20000 * 4; ++k) gyro_.samples.push_back({k * kPeriodNs / 4, 0});
  app_ = std::make_unique<app::App>(app::Hal{camera_, gyro_, clock_, link_, store_, watchdog_},
                                    app::Board{"stand-in", protocol::default_device_config()});
  app_->start();
  api_.backend = read::Backend::kHidraw;
  api_.init = [] { return 0; };
  api_.exit = [] { return 0; };
  api_.enumerate = &enumerate;
  api_.free_enumeration = &free_enumeration;
  api_.open_path = &open_path;
  api_.close = &close;
  api_.read_timeout = &read_timeout;
  api_.send_feature_report = &send_feature_report;
  api_.get_feature_report = &get_feature_report;
  api_.error = &error;
  g_device = this;
  read::use_stand_in_hidapi(&api_);
}

StandInDevice::~StandInDevice() {
  read::use_stand_in_hidapi(nullptr);
  g_device = nullptr;
}

bool StandInDevice::transfer() {
  ++transfers_;
  if (gone_after >= 0 && transfers_ > gone_after) gone_ = true;
  return !gone_ && drop.count(transfers_) == 0;
}

void StandInDevice::frame() {
  const size_t before = link_.inputs.size();
  app_->run_once();
  std::vector<std::vector<uint8_t>> chunks, others;
  for (size_t i = before; i < link_.inputs.size(); ++i)
    (link_.inputs[i][0] == protocol::kReportFeatureChunk ? chunks : others).push_back(link_.inputs[i]);
  if (chunks.empty()) return;
  link_.inputs.resize(before);
  std::vector<std::vector<uint8_t>>& last = last_answer_[chunks[0][2]];  // byte 2: the report answered
  if (replay_stale) link_.inputs.insert(link_.inputs.end(), last.begin(), last.end());
  link_.inputs.insert(link_.inputs.end(), chunks.begin(), chunks.end());
  link_.inputs.insert(link_.inputs.end(), others.begin(), others.end());
  last = chunks;
}

hid_device_info* StandInDevice::enumerate(unsigned short, unsigned short) {
  if (g_device == nullptr || g_device->gone_) return nullptr;
  auto* d = new hid_device_info{};
  d->path = const_cast<char*>("stand-in");
  d->vendor_id = protocol::kUsbVendorId;
  d->product_id = protocol::kUsbProductId;
  d->usage_page = protocol::kUsagePage;
  return d;
}

void StandInDevice::free_enumeration(hid_device_info* d) { delete d; }

hid_device* StandInDevice::open_path(const char*) {
  return g_device != nullptr && !g_device->gone_ ? handle() : nullptr;
}

void StandInDevice::close(hid_device*) {}

int StandInDevice::read_timeout(hid_device*, unsigned char* buf, size_t cap, int) {
  StandInDevice& d = *g_device;
  if (d.gone_) return -1;
  if (d.next_input_ == d.link_.inputs.size()) d.frame();
  if (d.next_input_ == d.link_.inputs.size()) return 0;
  const std::vector<uint8_t>& r = d.link_.inputs[d.next_input_++];
  const size_t n = r.size() < cap ? r.size() : cap;
  std::memcpy(buf, r.data(), n);
  return static_cast<int>(n);
}

int StandInDevice::send_feature_report(hid_device*, const unsigned char* data, size_t len) {
  StandInDevice& d = *g_device;
  if (!d.transfer()) return d.gone_ ? -1 : static_cast<int>(len);  // lost: acknowledged all the same
  d.link_.pending.push_back({data[0], true, std::vector<uint8_t>(data, data + len)});
  d.frame();
  return d.link_.replies.back().at(0) != 0 ? static_cast<int>(len) : -1;  // refused: a stall
}

int StandInDevice::get_feature_report(hid_device*, unsigned char* buf, size_t len) {
  StandInDevice& d = *g_device;
  const uint8_t id = buf[0];
  if (!d.transfer()) return -1;
  if (d.gadget) {  // answered by the USB stack itself: zeros
    std::memset(buf + 1, 0, len - 1);
    return static_cast<int>(len);
  }
  d.link_.pending.push_back({id, false, {}});
  d.frame();
  const std::vector<uint8_t>& r = d.link_.replies.back();
  if (r.empty() || r.size() > len) return -1;
  std::memcpy(buf, r.data(), r.size());
  return static_cast<int>(r.size());
}

const wchar_t* StandInDevice::error(hid_device*) {
  return g_device != nullptr && g_device->gone_ ? L"stand-in device gone" : L"";
}

}  // namespace lumavel::test
