// The firmware app's main loop against scripted HAL fakes: start-up and the
// configuration fallback, the gyro hand-over rule, the overrun counter,
// the watchdog, the measurement report and the feature requests.
#include <CppUTest/TestHarness.h>

#include <cstdint>
#include <memory>
#include <vector>

#include "app_env.hpp"
#include "fake_hal.hpp"
#include "lumavel/app/app.hpp"
#include "lumavel/protocol/device_config.hpp"
#include "lumavel/protocol/reports.hpp"

using lumavel::app::App;
using lumavel::app::RunState;
namespace protocol = lumavel::protocol;

namespace {

std::vector<uint8_t> encoded(const protocol::DeviceConfig& c) {
  std::vector<uint8_t> b(protocol::kConfigSize);
  b.resize(protocol::encode_config(c, b.data(), b.size()));
  return b;
}

protocol::Measurement measurement(const std::vector<uint8_t>& r) {
  protocol::Measurement m{};
  const protocol::DecodeResult res = protocol::decode_measurement(r.data(), r.size(), m);
  CHECK_TRUE_TEXT(res.ok(), protocol::to_string(res.error));
  return m;
}

}  // namespace

TEST_GROUP(AppStart) {
  std::unique_ptr<Env> env;
  void setup() override { env = std::make_unique<Env>(); }
  void teardown() override { env.reset(); }
};

TEST(AppStart, EmptyStoreRunsTheBoardDefaults) {
  CHECK_TRUE(env->app.start());
  CHECK_EQUAL(protocol::kConfigDefaults, env->app.config_source());
  CHECK_EQUAL(static_cast<int>(protocol::ConfigField::kOk), static_cast<int>(env->app.config_status()));
  CHECK_EQUAL(100000u, env->app.device_config().tau_us);
  CHECK_TRUE(env->watchdog.kicks > 0);
}

TEST(AppStart, ValidStoredConfigurationIsUsed) {
  protocol::DeviceConfig c = protocol::default_device_config();
  c.tau_us = 300000;
  env->store.blob = encoded(c);
  CHECK_TRUE(env->app.start());
  CHECK_EQUAL(protocol::kConfigStored, env->app.config_source());
  CHECK_EQUAL(300000u, env->app.device_config().tau_us);
  CHECK_EQUAL(300000u, env->app.estimator().config().tau_us);
}

TEST(AppStart, CorruptStoreFallsBackToDefaults) {
  protocol::DeviceConfig c = protocol::default_device_config();
  c.tau_us = 300000;
  env->store.blob = encoded(c);
  env->store.blob[40] ^= 1;  // CRC no longer matches
  CHECK_TRUE(env->app.start());
  CHECK_EQUAL(protocol::kConfigDefaults, env->app.config_source());
  CHECK_EQUAL(100000u, env->app.device_config().tau_us);
  CHECK_EQUAL(100000u, env->app.estimator().config().tau_us);
}

TEST(AppStart, StoredConfigurationForAnotherCameraIsRefused) {
  protocol::DeviceConfig c = protocol::default_device_config();
  env->camera.w = 48;  // the stored 40-column configuration does not fit this camera
  env->store.blob = encoded(c);
  CHECK_FALSE(env->app.start());  // and neither do the 40-column defaults
  CHECK_EQUAL(static_cast<int>(protocol::ConfigField::kWidth), static_cast<int>(env->app.config_status()));
  CHECK_TRUE(RunState::kUnconfigured == env->app.run_once());
}

TEST_GROUP(AppLoop) {
  std::unique_ptr<Env> env;
  void setup() override {
    env = std::make_unique<Env>();
    for (uint64_t t = 0; t < 40 * kPeriod; t += 2000000) env->gyro.samples.push_back({t, 1 << 20});
  }
  void teardown() override { env.reset(); }
  void frames(std::vector<uint64_t> t) { env->camera.times = std::move(t); }
};

TEST(AppLoop, PushesGyroSamplesUpToTheFirstAtOrAfterTheFrame) {
  frames({5000000, 5500000, 9000000});
  CHECK_TRUE(env->app.start());
  CHECK_TRUE(RunState::kFrame == env->app.run_once());
  CHECK_EQUAL(4u, env->gyro.next);  // 0, 2, 4 ms and the first at/after 5 ms: 6 ms
  CHECK_TRUE(RunState::kFrame == env->app.run_once());
  CHECK_EQUAL(4u, env->gyro.next);  // 6 ms already covers 5.5 ms
  CHECK_TRUE(RunState::kFrame == env->app.run_once());
  CHECK_EQUAL(6u, env->gyro.next);  // 8 and 10 ms
  CHECK_EQUAL(6u, env->app.counters().gyro_samples);
}

TEST(AppLoop, StepsWithWhatTheGyroHasWhenTheNextSampleIsLate) {
  frames({5000000});
  env->gyro.ready = 2;  // only 0 and 2 ms measured so far
  CHECK_TRUE(env->app.start());
  CHECK_TRUE(RunState::kFrame == env->app.run_once());
  CHECK_EQUAL(2u, env->gyro.next);
  CHECK_EQUAL(1u, env->link.inputs.size());
}

TEST(AppLoop, OneMeasurementReportPerFrameWithSequenceAndTime) {
  frames({kPeriod, 2 * kPeriod, 3 * kPeriod});
  CHECK_TRUE(env->app.start());
  env->app.run();
  CHECK_EQUAL(3u, env->link.inputs.size());
  for (uint16_t i = 0; i < 3; ++i) {
    const protocol::Measurement m = measurement(env->link.inputs[i]);
    CHECK_EQUAL(i, m.seq);
    CHECK_EQUAL((i + 1) * kPeriod, m.t_ns);
    CHECK_EQUAL(0u, m.overruns);
  }
  CHECK_EQUAL(3u, env->app.counters().frames);
}

TEST(AppLoop, TimestampGapsAndCaptureErrorsCountAsOverruns) {
  // Frames 4, 5 and 6 missing (gap of 4 periods), then one capture error.
  frames({kPeriod, 2 * kPeriod, 3 * kPeriod, 7 * kPeriod, UINT64_MAX, 9 * kPeriod});
  CHECK_TRUE(env->app.start());
  env->app.run();
  CHECK_EQUAL(5u, env->link.inputs.size());
  CHECK_EQUAL(0u, measurement(env->link.inputs[2]).overruns);
  CHECK_EQUAL(3u, measurement(env->link.inputs[3]).overruns);
  // 7 -> 9 is one more missing frame besides the capture error.
  CHECK_EQUAL(5u, measurement(env->link.inputs[4]).overruns);
  CHECK_EQUAL(1u, env->app.counters().capture_errors);
}

TEST(AppLoop, KicksTheWatchdogEveryFrame) {
  frames({kPeriod, 2 * kPeriod, 3 * kPeriod, 4 * kPeriod});
  CHECK_TRUE(env->app.start());
  const int after_start = env->watchdog.kicks;
  env->app.run();
  CHECK_EQUAL(after_start + 5, env->watchdog.kicks);  // 4 frames + the call that sees the end
}

TEST(AppLoop, CountsReportsTheLinkRefused) {
  frames({kPeriod, 2 * kPeriod});
  env->link.refuse = true;
  CHECK_TRUE(env->app.start());
  env->app.run();
  CHECK_EQUAL(2u, env->app.counters().reports_dropped);
}

TEST_GROUP(AppFeatures) {
  std::unique_ptr<Env> env;
  void setup() override {
    env = std::make_unique<Env>();
    for (uint64_t k = 1; k <= 8; ++k) env->camera.times.push_back(k * kPeriod);
    CHECK_TRUE(env->app.start());
  }
  void teardown() override { env.reset(); }
  void request(uint8_t id, bool is_set, std::vector<uint8_t> data = {}) {
    env->link.pending.push_back({id, is_set, std::move(data)});
    const size_t before = env->link.replies.size();
    CHECK_TRUE(RunState::kFrame == env->app.run_once());
    CHECK_EQUAL(before + 1, env->link.replies.size());
  }
};

TEST(AppFeatures, DeviceInfoNamesTheBoardAndCapacities) {
  request(protocol::kReportDeviceInfo, false);
  CHECK_EQUAL(1u, env->link.replies.size());
  protocol::DeviceInfo d{};
  CHECK_TRUE(protocol::decode_device_info(env->link.replies[0].data(), env->link.replies[0].size(), d).ok());
  STRCMP_EQUAL("test-board", d.board);
  CHECK_EQUAL(40, d.width);
  CHECK_EQUAL(30, d.height);
  CHECK_EQUAL(lumavel::kMaxColumns, d.max_columns);
  CHECK_EQUAL(protocol::kConfigDefaults, d.config_source);
}

TEST(AppFeatures, GetConfigReturnsTheRunningConfiguration) {
  request(protocol::kReportConfig, false);
  protocol::DeviceConfig c{};
  CHECK_TRUE(protocol::decode_config(env->link.replies[0].data(), env->link.replies[0].size(), c).ok());
  MEMCMP_EQUAL(encoded(protocol::default_device_config()).data(), env->link.replies[0].data(), protocol::kConfigSize);
}

TEST(AppFeatures, SetConfigAppliesAndPersists) {
  protocol::DeviceConfig c = protocol::default_device_config();
  c.tau_us = 250000;
  request(protocol::kReportConfig, true, encoded(c));
  CHECK_EQUAL(1, env->link.replies[0][0]);
  CHECK_EQUAL(250000u, env->app.estimator().config().tau_us);
  CHECK_EQUAL(protocol::kConfigSetByHost, env->app.config_source());
  CHECK_TRUE(encoded(c) == env->store.blob);
}

TEST(AppFeatures, CorruptSetIsRefusedAndTheOldConfigurationKept) {
  protocol::DeviceConfig c = protocol::default_device_config();
  c.tau_us = 250000;
  std::vector<uint8_t> r = encoded(c);
  r[67] ^= 0x10;
  request(protocol::kReportConfig, true, r);
  CHECK_EQUAL(0, env->link.replies[0][0]);
  CHECK_EQUAL(100000u, env->app.estimator().config().tau_us);
  CHECK_EQUAL(0, env->store.saves);
  CHECK_EQUAL(static_cast<int>(protocol::ConfigField::kMalformed), static_cast<int>(env->app.config_status()));
}

TEST(AppFeatures, SetForAnotherResolutionNamesTheField) {
  protocol::DeviceConfig c = protocol::default_device_config();
  c.height = 20;  // valid in itself, but the camera delivers 30 rows
  request(protocol::kReportConfig, true, encoded(c));
  CHECK_EQUAL(0, env->link.replies[0][0]);
  CHECK_EQUAL(static_cast<int>(protocol::ConfigField::kHeight), static_cast<int>(env->app.config_status()));
  CHECK_EQUAL(30, env->app.estimator().config().height);
}

TEST(AppFeatures, SetThatCannotBePersistedStillAppliesAndSaysSo) {
  protocol::DeviceConfig c = protocol::default_device_config();
  c.tau_us = 200000;
  env->store.refuse_save = true;
  request(protocol::kReportConfig, true, encoded(c));
  CHECK_EQUAL(0, env->link.replies[0][0]);  // the host is told it failed ...
  CHECK_EQUAL(200000u, env->app.estimator().config().tau_us);  // ... though it runs until reboot
  CHECK_EQUAL(static_cast<int>(protocol::ConfigField::kStore), static_cast<int>(env->app.config_status()));
}

TEST(AppFeatures, MailboxSendsTheConfigurationAsInputChunks) {
  std::vector<uint8_t> m(protocol::kMailboxSize);
  protocol::encode_mailbox_request(protocol::kReportConfig, 0x42, m.data(), m.size());
  request(protocol::kReportMailbox, true, m);
  CHECK_EQUAL(1, env->link.replies[0][0]);
  std::vector<uint8_t> whole;
  for (const auto& in : env->link.inputs) {
    if (in[0] != protocol::kReportFeatureChunk) continue;
    protocol::FeatureChunk c{};
    CHECK_TRUE(protocol::decode_feature_chunk(in.data(), in.size(), c).ok());
    CHECK_EQUAL(0x42, c.tag);  // the request's tag, in every chunk
    CHECK_EQUAL(whole.size(), c.offset);
    whole.insert(whole.end(), c.data, c.data + c.length);
  }
  CHECK_TRUE(encoded(protocol::default_device_config()) == whole);
}

TEST(AppFeatures, ANewerMailboxRequestReplacesOneNotYetAnswered) {
  // Two requests served in the same poll: only the later one is answered,
  // with its own tag, so the host waiting for it never takes the other.
  std::vector<uint8_t> a(protocol::kMailboxSize), b(protocol::kMailboxSize);
  protocol::encode_mailbox_request(protocol::kReportConfig, 7, a.data(), a.size());
  protocol::encode_mailbox_request(protocol::kReportDeviceInfo, 8, b.data(), b.size());
  env->link.pending.push_back({protocol::kReportMailbox, true, a});
  env->link.pending.push_back({protocol::kReportMailbox, true, b});
  CHECK_TRUE(RunState::kFrame == env->app.run_once());
  int chunks = 0;
  for (const auto& in : env->link.inputs) {
    if (in[0] != protocol::kReportFeatureChunk) continue;
    protocol::FeatureChunk c{};
    CHECK_TRUE(protocol::decode_feature_chunk(in.data(), in.size(), c).ok());
    CHECK_EQUAL(8, c.tag);
    CHECK_EQUAL(protocol::kReportDeviceInfo, c.report_id);
    ++chunks;
  }
  CHECK_EQUAL(1, chunks);
}

TEST(AppFeatures, UnknownReportsStall) {
  request(0x7E, false);
  request(0x7E, true, {0x7E, 1, 2});
  CHECK_EQUAL(0u, env->link.replies[0].size());
  CHECK_EQUAL(0, env->link.replies[1][0]);
}
