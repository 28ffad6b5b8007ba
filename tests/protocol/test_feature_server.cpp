#include <CppUTest/TestHarness.h>

#include <cstring>

#include "lumavel/protocol/feature_server.hpp"

using namespace lumavel::protocol;

namespace {

struct MemoryStore : lumavel::hal::ConfigStore {
  uint8_t blob[128] = {};
  size_t size = 0;
  bool fail_save = false;
  int saves = 0;
  size_t load(uint8_t* buf, size_t cap) override {
    if (size > cap) return 0;
    std::memcpy(buf, blob, size);
    return size;
  }
  bool save(const uint8_t* buf, size_t len) override {
    if (fail_save || len > sizeof blob) return false;
    std::memcpy(blob, buf, len);
    size = len;
    ++saves;
    return true;
  }
};

struct App {
  bool refuse = false;
  int applied = 0;
  uint16_t width = 0;
};

ConfigField apply(void* ctx, const DeviceConfig& c) {
  App& a = *static_cast<App*>(ctx);
  if (a.refuse) return ConfigField::kEstimator;
  ++a.applied;
  a.width = c.width;
  return ConfigField::kOk;
}

DeviceInfo identity() {
  DeviceInfo d{};
  std::strcpy(d.board, "test");
  d.max_columns = 160;
  d.max_rows = 128;
  d.max_kernels = 6;
  return d;
}

DeviceConfig other() {
  DeviceConfig c = default_device_config();
  c.width = 80;
  c.cu[0] = c.cu[1] = 39 * 65536;
  return c;
}

}  // namespace

TEST_GROUP(FeatureServer) {
  MemoryStore store;
  App app;
};

TEST(FeatureServer, BootsOnDefaultsWithEmptyStore) {
  FeatureServer s(identity(), &store, apply, &app);
  CHECK_TRUE(ConfigField::kOk == s.boot(default_device_config()));
  CHECK_EQUAL(40, app.width);
  CHECK_EQUAL(kConfigDefaults, s.info().config_source);
  CHECK_EQUAL(40, s.info().width);
}

TEST(FeatureServer, SetAppliesPersistsAndGetsBack) {
  FeatureServer s(identity(), &store, apply, &app);
  s.boot(default_device_config());
  uint8_t buf[kConfigSize];
  encode_config(other(), buf, sizeof buf);
  CHECK_EQUAL(1u, FeatureServer::handle(&s, kReportConfig, true, buf, sizeof buf, sizeof buf));
  CHECK_EQUAL(80, app.width);
  CHECK_EQUAL(1, store.saves);
  uint8_t got[kMaxReportSize];
  CHECK_EQUAL(kConfigSize, FeatureServer::handle(&s, kReportConfig, false, got, 0, sizeof got));
  MEMCMP_EQUAL(buf, got, kConfigSize);
  CHECK_EQUAL(kDeviceInfoSize, FeatureServer::handle(&s, kReportDeviceInfo, false, got, 0, sizeof got));
  DeviceInfo info{};
  CHECK_TRUE(decode_device_info(got, kDeviceInfoSize, info).ok());
  CHECK_EQUAL(80, info.width);
  CHECK_EQUAL(kConfigSetByHost, info.config_source);
  CHECK_EQUAL(0, info.config_status);

  // A reboot comes back on the stored configuration.
  App app2;
  FeatureServer s2(identity(), &store, apply, &app2);
  CHECK_TRUE(ConfigField::kOk == s2.boot(default_device_config()));
  CHECK_EQUAL(80, app2.width);
  CHECK_EQUAL(kConfigStored, s2.info().config_source);
}

TEST(FeatureServer, RefusedSetsChangeNothingAndSayWhy) {
  FeatureServer s(identity(), &store, apply, &app);
  s.boot(default_device_config());
  uint8_t buf[kConfigSize];
  DeviceConfig bad = other();
  bad.tau_us = 1;
  encode_config(bad, buf, sizeof buf);
  CHECK_EQUAL(0u, FeatureServer::handle(&s, kReportConfig, true, buf, sizeof buf, sizeof buf));
  CHECK_EQUAL(static_cast<int>(ConfigField::kTau), s.info().config_status);

  encode_config(other(), buf, sizeof buf);
  buf[10] ^= 1;  // CRC now wrong
  CHECK_EQUAL(0u, FeatureServer::handle(&s, kReportConfig, true, buf, sizeof buf, sizeof buf));
  CHECK_EQUAL(static_cast<int>(ConfigField::kMalformed), s.info().config_status);

  app.refuse = true;
  encode_config(other(), buf, sizeof buf);
  CHECK_EQUAL(0u, FeatureServer::handle(&s, kReportConfig, true, buf, sizeof buf, sizeof buf));
  CHECK_EQUAL(static_cast<int>(ConfigField::kEstimator), s.info().config_status);

  CHECK_EQUAL(40, s.config().width);
  CHECK_EQUAL(0, store.saves);
  CHECK_EQUAL(0u, FeatureServer::handle(&s, kReportDeviceInfo, true, buf, sizeof buf, sizeof buf));
  CHECK_EQUAL(0u, FeatureServer::handle(&s, kReportMeasurement, false, buf, 0, sizeof buf));
}

TEST(FeatureServer, StoreFailureReported) {
  store.fail_save = true;
  FeatureServer s(identity(), &store, apply, &app);
  s.boot(default_device_config());
  uint8_t buf[kConfigSize];
  encode_config(other(), buf, sizeof buf);
  CHECK_EQUAL(0u, FeatureServer::handle(&s, kReportConfig, true, buf, sizeof buf, sizeof buf));
  CHECK_EQUAL(static_cast<int>(ConfigField::kStore), s.info().config_status);
}

TEST(FeatureServer, CorruptStoreFallsBackToDefaults) {
  encode_config(other(), store.blob, sizeof store.blob);
  store.size = kConfigSize;
  store.blob[20] ^= 0x40;
  FeatureServer s(identity(), &store, apply, &app);
  CHECK_TRUE(ConfigField::kOk == s.boot(default_device_config()));
  CHECK_EQUAL(40, s.config().width);
  CHECK_EQUAL(kConfigDefaults, s.info().config_source);
}
