#include <CppUTest/TestHarness.h>

#include <cmath>
#include <vector>

#include "lumavel/host/hid_sender.hpp"
#include "lumavel/protocol/device_config.hpp"

using namespace lumavel;

namespace {

// A link that records reports, refuses them while `busy`, and replays one
// scripted feature request per poll.
struct FakeLink : hal::ReportLink {
  std::vector<std::vector<uint8_t>>* sent;
  bool* busy;
  std::vector<uint8_t>* reply;
  uint8_t ask_id = 0;
  bool ask_set = false;
  std::vector<uint8_t> set_data;
  size_t* set_result;
  bool send_input(const uint8_t* r, size_t len) override {
    if (*busy) return false;
    sent->emplace_back(r, r + len);
    return true;
  }
  void poll_features(FeatureHandler h, void* ctx) override {
    if (ask_id == 0) return;
    uint8_t buf[128] = {};
    if (ask_set) {
      std::copy(set_data.begin(), set_data.end(), buf);
      *set_result = h(ctx, ask_id, true, buf, set_data.size(), sizeof buf);
    } else {
      const size_t n = h(ctx, ask_id, false, buf, 0, sizeof buf);
      reply->assign(buf, buf + n);
    }
    ask_id = 0;
  }
};

// The flash page of a simulated device, in memory; shared across restarts.
struct MemoryStore : hal::ConfigStore {
  std::vector<uint8_t>* blob;
  explicit MemoryStore(std::vector<uint8_t>* b) : blob(b) {}
  size_t load(uint8_t* buf, size_t cap) override {
    if (blob->size() > cap) return 0;
    std::copy(blob->begin(), blob->end(), buf);
    return blob->size();
  }
  bool save(const uint8_t* buf, size_t len) override {
    blob->assign(buf, buf + len);
    return true;
  }
};

}  // namespace

TEST_GROUP(HidSender) {
  std::vector<std::vector<uint8_t>> sent;
  bool busy = false;
  std::vector<uint8_t> reply;
  size_t set_result = 99;
  FakeLink* link = nullptr;
  std::unique_ptr<host::HidSender> sender;
  void setup() override {
    auto l = std::make_unique<FakeLink>();
    l->sent = &sent;
    l->busy = &busy;
    l->reply = &reply;
    l->set_result = &set_result;
    link = l.get();
    host::HidSenderOptions o;
    o.first_wait_ms = 20;
    o.wait_ms = 5;
    o.min_interval_us = 0;
    sender = std::make_unique<host::HidSender>(std::move(l), o);
  }
};

TEST(HidSender, QuantisesToTheReportFormats) {
  const protocol::Measurement m =
      host::quantise_measurement(123, 7, 1.5, -2.25, -3.0, 0x41);
  CHECK_EQUAL(98304, m.v);
  CHECK_TRUE(m.distance == -9663676416LL);  // -2.25 * 2^32
  CHECK_EQUAL(static_cast<int32_t>(std::lround(-3.0 * 268435456.0)), m.heading);
  CHECK_EQUAL(7u, m.frame_index);
  CHECK_EQUAL(0x41, m.status);
}

TEST(HidSender, HeadingWrappedIntoMinusPiPi) {
  const double pi = 3.14159265358979323846;
  CHECK_EQUAL(-fx::kPiQ28, host::quantise_measurement(0, 0, 0, 0, pi, 0).heading);
  const int32_t h = host::quantise_measurement(0, 0, 0, 0, pi + 0.5, 0).heading;
  CHECK_EQUAL(static_cast<int32_t>(std::lround((0.5 - pi) * 268435456.0)), h);
}

TEST(HidSender, OneReportPerEstimateWithSequenceAndOverruns) {
  CHECK_TRUE(sender->send(1000, 1.0, 0.5, 0.1, 0));
  busy = true;
  CHECK_FALSE(sender->send(2000, 1.0, 0.6, 0.1, 0));  // host not reading: an overrun
  busy = false;
  CHECK_TRUE(sender->send(3000, 1.0, 0.7, 0.1, 0));
  CHECK_EQUAL(2u, sent.size());
  protocol::Measurement a{}, b{};
  CHECK_TRUE(protocol::decode_measurement(sent[0].data(), sent[0].size(), a).ok());
  CHECK_TRUE(protocol::decode_measurement(sent[1].data(), sent[1].size(), b).ok());
  CHECK_EQUAL(0, a.seq);
  CHECK_EQUAL(2, b.seq);  // the gap shows the lost report to the host
  CHECK_EQUAL(0, a.overruns);
  CHECK_EQUAL(1, b.overruns);
  CHECK_EQUAL(1, sender->overruns());
  CHECK_TRUE(b.t_ns == 3000u);
}

TEST(HidSender, ServesInfoAndRefusesConfigSets) {
  sender->set_resolution(64, 48);
  link->ask_id = protocol::kReportDeviceInfo;
  sender->poll();
  protocol::DeviceInfo info{};
  CHECK_TRUE(protocol::decode_device_info(reply.data(), reply.size(), info).ok());
  STRCMP_EQUAL("lumavel-sim", info.board);
  CHECK_EQUAL(64, info.width);
  CHECK_EQUAL(48, info.height);

  uint8_t cfg[protocol::kConfigSize];
  protocol::encode_config(protocol::default_device_config(), cfg, sizeof cfg);
  link->ask_id = protocol::kReportConfig;
  link->ask_set = true;
  link->set_data.assign(cfg, cfg + sizeof cfg);
  sender->poll();
  CHECK_EQUAL(0u, set_result);
  link->ask_id = protocol::kReportDeviceInfo;
  link->ask_set = false;
  sender->poll();
  CHECK_TRUE(protocol::decode_device_info(reply.data(), reply.size(), info).ok());
  CHECK_EQUAL(static_cast<int>(protocol::ConfigField::kEstimator), info.config_status);
  CHECK_EQUAL(64, info.width);  // unchanged
}

// With a config store (`lumavel-sim run --hid-config FILE`): validated sets
// are accepted, served back and persisted; a restarted sender serves them.
TEST(HidSender, WithAStoreAcceptsAndPersistsConfigSets) {
  std::vector<uint8_t> blob;
  auto fresh_sender = [&]() {
    auto l = std::make_unique<FakeLink>();
    l->sent = &sent;
    l->busy = &busy;
    l->reply = &reply;
    l->set_result = &set_result;
    link = l.get();
    sender = std::make_unique<host::HidSender>(std::move(l), host::HidSenderOptions{},
                                               std::make_unique<MemoryStore>(&blob));
    sender->set_resolution(64, 48);
  };
  auto get = [&](uint8_t id) {
    link->ask_id = id;
    link->ask_set = false;
    sender->poll();
  };
  auto set = [&](const protocol::DeviceConfig& c) {
    uint8_t cfg[protocol::kConfigSize];
    protocol::encode_config(c, cfg, sizeof cfg);
    link->ask_id = protocol::kReportConfig;
    link->ask_set = true;
    link->set_data.assign(cfg, cfg + sizeof cfg);
    sender->poll();
  };
  fresh_sender();
  protocol::DeviceInfo info{};
  protocol::DeviceConfig got{};
  get(protocol::kReportConfig);
  CHECK_TRUE(protocol::decode_config(reply.data(), reply.size(), got).ok());
  CHECK_EQUAL(64, got.width);  // nothing stored yet: the recording's configuration

  protocol::DeviceConfig c = protocol::default_device_config();
  c.width = 80;
  c.tau_us = 250000;
  set(c);
  CHECK_EQUAL(1u, set_result);
  CHECK_EQUAL(protocol::kConfigSize, blob.size());
  get(protocol::kReportConfig);
  CHECK_TRUE(protocol::decode_config(reply.data(), reply.size(), got).ok());
  CHECK_EQUAL(80, got.width);
  CHECK_EQUAL(250000u, got.tau_us);
  get(protocol::kReportDeviceInfo);
  CHECK_TRUE(protocol::decode_device_info(reply.data(), reply.size(), info).ok());
  CHECK_EQUAL(0, info.config_status);
  CHECK_EQUAL(protocol::kConfigSetByHost, info.config_source);

  protocol::DeviceConfig bad = c;  // out of range: refused, the store keeps c
  bad.tau_us = 5;
  const std::vector<uint8_t> kept = blob;
  set(bad);
  CHECK_EQUAL(0u, set_result);
  CHECK_TRUE(kept == blob);
  get(protocol::kReportDeviceInfo);
  CHECK_TRUE(protocol::decode_device_info(reply.data(), reply.size(), info).ok());
  CHECK_EQUAL(static_cast<int>(protocol::ConfigField::kTau), info.config_status);

  fresh_sender();  // a restart serves the stored configuration
  get(protocol::kReportConfig);
  CHECK_TRUE(protocol::decode_config(reply.data(), reply.size(), got).ok());
  CHECK_EQUAL(80, got.width);
  CHECK_EQUAL(250000u, got.tau_us);
  get(protocol::kReportDeviceInfo);
  CHECK_TRUE(protocol::decode_device_info(reply.data(), reply.size(), info).ok());
  CHECK_EQUAL(protocol::kConfigStored, info.config_source);
}

TEST(HidSender, FileLinksAreNotPaced) {
  CHECK_EQUAL(0, host::hid_sender_options_for("file:x.hidrep").min_interval_us);
  CHECK_EQUAL(1000, host::hid_sender_options_for("uhid").min_interval_us);
  CHECK_EQUAL(30000, host::hid_sender_options_for("hidg:/dev/hidg0").first_wait_ms);
}
