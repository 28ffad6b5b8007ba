#include <CppUTest/TestHarness.h>

#include <cstring>

#include "lumavel/app/feature_server.hpp"

using namespace lumavel::protocol;
using lumavel::app::FeatureServer;

namespace {

struct MemoryStore : lumavel::hal::ConfigStore {
  uint8_t blob[kMaxStoredConfigSize] = {};
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
  lumavel::EdgeOffsetQ15 lens[2][kMaxLensEdges] = {};  // what the last apply was given
  bool had_lens[2] = {false, false};
};

ConfigField apply(void* ctx, const DeviceConfig& c, const lumavel::EdgeOffsetQ15* const lens[2]) {
  App& a = *static_cast<App*>(ctx);
  if (a.refuse) return ConfigField::kEstimator;
  ++a.applied;
  a.width = c.width;
  for (int i = 0; i < 2; ++i) {
    a.had_lens[i] = lens[i] != nullptr;
    for (int u = 0; lens[i] && u <= c.width; ++u) a.lens[i][u] = lens[i][u];
  }
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

namespace {

// Uploads `edges` values of camera `cam` in 24-value pieces; false if one is refused.
bool upload(FeatureServer& s, uint8_t cam, const lumavel::EdgeOffsetQ15* v, int edges) {
  for (int first = 0; first < edges; first += static_cast<int>(kLensChunkEdges)) {
    LensChunk c{};
    c.camera = cam;
    c.first = static_cast<uint8_t>(first);
    const int n = edges - first < static_cast<int>(kLensChunkEdges) ? edges - first : static_cast<int>(kLensChunkEdges);
    c.count = static_cast<uint8_t>(n);
    for (int i = 0; i < n; ++i) c.offsets[i] = v[first + i];
    uint8_t buf[kLensChunkSize];
    encode_lens_chunk(c, buf, sizeof buf);
    if (FeatureServer::handle(&s, kReportLens, true, buf, sizeof buf, sizeof buf) != 1) return false;
  }
  return true;
}

// A lens table for `width` columns: a smooth barrel-like correction.
void table(lumavel::EdgeOffsetQ15* v, int width, int scale) {
  for (int u = 0; u <= width; ++u) {
    const int x = 2 * u - width;
    v[u] = static_cast<lumavel::EdgeOffsetQ15>(scale * x * x * x / (width * width * width));
  }
}

DeviceConfig with_lens(uint8_t lens, const lumavel::EdgeOffsetQ15* t0, const lumavel::EdgeOffsetQ15* t1) {
  DeviceConfig c = other();
  c.lens = lens;
  const lumavel::EdgeOffsetQ15* const t[2] = {t0, t1};
  c.lens_crc = lens_crc(t, lens, static_cast<uint16_t>(c.width + 1));
  return c;
}

// Reads the piece at {cam, first} back through a select and a get.
LensChunk read_piece(FeatureServer& s, uint8_t cam, uint8_t first) {
  LensChunk sel{};
  sel.camera = cam;
  sel.first = first;
  uint8_t buf[kLensChunkSize];
  encode_lens_chunk(sel, buf, sizeof buf);
  CHECK_EQUAL(1u, FeatureServer::handle(&s, kReportLens, true, buf, sizeof buf, sizeof buf));
  uint8_t got[kMaxReportSize];
  CHECK_EQUAL(kLensChunkSize, FeatureServer::handle(&s, kReportLens, false, got, 0, sizeof got));
  LensChunk out{};
  CHECK_TRUE(decode_lens_chunk(got, kLensChunkSize, out).ok());
  return out;
}

}  // namespace

TEST(FeatureServer, LensTablesAreAppliedStoredAndReadBack) {
  FeatureServer s(identity(), &store, apply, &app);
  s.boot(default_device_config());
  static lumavel::EdgeOffsetQ15 t0[kMaxLensEdges], t1[kMaxLensEdges];
  table(t0, 80, 900);
  table(t1, 80, -700);
  CHECK_TRUE(upload(s, 0, t0, 81));
  CHECK_TRUE(upload(s, 1, t1, 81));
  uint8_t buf[kConfigSize];
  encode_config(with_lens(kLensCam0 | kLensCam1, t0, t1), buf, sizeof buf);
  CHECK_EQUAL(1u, FeatureServer::handle(&s, kReportConfig, true, buf, sizeof buf, sizeof buf));
  CHECK_TRUE(app.had_lens[0] && app.had_lens[1]);
  MEMCMP_EQUAL(t0, app.lens[0], 81 * sizeof t0[0]);
  MEMCMP_EQUAL(t1, app.lens[1], 81 * sizeof t1[0]);
  CHECK_EQUAL(kConfigSize + 2 * 81 * 2, store.size);

  // Read back piece by piece: the last piece of 81 holds 81 - 72 = 9 values.
  const LensChunk last = read_piece(s, 1, 72);
  CHECK_EQUAL(9, last.count);
  MEMCMP_EQUAL(t1 + 72, last.offsets, 9 * sizeof t1[0]);
  CHECK_EQUAL(0, read_piece(s, 1, 81).count);

  // A reboot applies the stored tables.
  App app2;
  FeatureServer s2(identity(), &store, apply, &app2);
  CHECK_TRUE(ConfigField::kOk == s2.boot(default_device_config()));
  CHECK_EQUAL(kConfigStored, s2.info().config_source);
  CHECK_TRUE(app2.had_lens[0] && app2.had_lens[1]);
  MEMCMP_EQUAL(t0, app2.lens[0], 81 * sizeof t0[0]);
  const LensChunk first = read_piece(s2, 0, 24);
  CHECK_EQUAL(24, first.count);
  MEMCMP_EQUAL(t0 + 24, first.offsets, 24 * sizeof t0[0]);
}

TEST(FeatureServer, PartialOrMismatchedLensIsRefusedAsLens) {
  FeatureServer s(identity(), &store, apply, &app);
  s.boot(default_device_config());
  static lumavel::EdgeOffsetQ15 t0[kMaxLensEdges];
  table(t0, 80, 900);
  uint8_t buf[kConfigSize];
  // Named but never uploaded.
  encode_config(with_lens(kLensCam0, t0, nullptr), buf, sizeof buf);
  CHECK_EQUAL(0u, FeatureServer::handle(&s, kReportConfig, true, buf, sizeof buf, sizeof buf));
  CHECK_EQUAL(static_cast<int>(ConfigField::kLens), s.info().config_status);
  // Incomplete: 80 of 81 edges.
  CHECK_TRUE(upload(s, 0, t0, 80));
  CHECK_EQUAL(0u, FeatureServer::handle(&s, kReportConfig, true, buf, sizeof buf, sizeof buf));
  CHECK_EQUAL(static_cast<int>(ConfigField::kLens), s.info().config_status);
  // Complete but not the table the configuration was made for.
  CHECK_TRUE(upload(s, 0, t0, 81));
  DeviceConfig c = with_lens(kLensCam0, t0, nullptr);
  c.lens_crc ^= 1;
  encode_config(c, buf, sizeof buf);
  CHECK_EQUAL(0u, FeatureServer::handle(&s, kReportConfig, true, buf, sizeof buf, sizeof buf));
  CHECK_EQUAL(static_cast<int>(ConfigField::kLens), s.info().config_status);
  CHECK_EQUAL(40, s.config().width);
  CHECK_EQUAL(0, store.saves);
  // Every set ends an upload: the right one goes through once the table is sent again.
  encode_config(with_lens(kLensCam0, t0, nullptr), buf, sizeof buf);
  CHECK_EQUAL(0u, FeatureServer::handle(&s, kReportConfig, true, buf, sizeof buf, sizeof buf));
  CHECK_TRUE(upload(s, 0, t0, 81));
  CHECK_EQUAL(1u, FeatureServer::handle(&s, kReportConfig, true, buf, sizeof buf, sizeof buf));
  CHECK_TRUE(app.had_lens[0]);
  CHECK_FALSE(app.had_lens[1]);
}

TEST(FeatureServer, LensPiecesOutOfOrderOrBeyondCapacityAreRefused) {
  FeatureServer s(identity(), &store, apply, &app);
  s.boot(default_device_config());
  LensChunk c{};
  c.camera = 0;
  c.first = 24;  // nothing before it
  c.count = 24;
  uint8_t buf[kLensChunkSize];
  encode_lens_chunk(c, buf, sizeof buf);
  CHECK_EQUAL(0u, FeatureServer::handle(&s, kReportLens, true, buf, sizeof buf, sizeof buf));
  CHECK_EQUAL(static_cast<int>(ConfigField::kLens), s.info().lens_status);
  CHECK_EQUAL(0, s.info().config_status);  // the last configuration set is still the boot's, accepted
  c.first = static_cast<uint8_t>(kMaxLensEdges - 10);  // past the build's columns + 1
  encode_lens_chunk(c, buf, sizeof buf);
  CHECK_EQUAL(0u, FeatureServer::handle(&s, kReportLens, true, buf, sizeof buf, sizeof buf));
  encode_lens_chunk(c, buf, sizeof buf);
  buf[7] ^= 1;  // CRC
  CHECK_EQUAL(0u, FeatureServer::handle(&s, kReportLens, true, buf, sizeof buf, sizeof buf));
  CHECK_EQUAL(static_cast<int>(ConfigField::kMalformed), s.info().lens_status);
}

TEST(FeatureServer, StoredLensWithBadTableFallsBackToDefaults) {
  FeatureServer s(identity(), &store, apply, &app);
  s.boot(default_device_config());
  static lumavel::EdgeOffsetQ15 t0[kMaxLensEdges];
  table(t0, 80, 900);
  CHECK_TRUE(upload(s, 0, t0, 81));
  uint8_t buf[kConfigSize];
  encode_config(with_lens(kLensCam0, t0, nullptr), buf, sizeof buf);
  CHECK_EQUAL(1u, FeatureServer::handle(&s, kReportConfig, true, buf, sizeof buf, sizeof buf));
  store.blob[kConfigSize + 11] ^= 0x10;  // a table byte: lens_crc no longer matches
  App app2;
  FeatureServer s2(identity(), &store, apply, &app2);
  CHECK_TRUE(ConfigField::kOk == s2.boot(default_device_config()));
  CHECK_EQUAL(kConfigDefaults, s2.info().config_source);
  CHECK_FALSE(app2.had_lens[0]);
  store.blob[kConfigSize + 11] ^= 0x10;
  store.size -= 2;  // truncated tables
  FeatureServer s3(identity(), &store, apply, &app2);
  s3.boot(default_device_config());
  CHECK_EQUAL(kConfigDefaults, s3.info().config_source);
}

namespace {

// Sets a configuration; returns whether the device accepted it.
bool set(FeatureServer& s, const DeviceConfig& c) {
  uint8_t buf[kConfigSize];
  encode_config(c, buf, sizeof buf);
  return FeatureServer::handle(&s, kReportConfig, true, buf, sizeof buf, sizeof buf) == 1;
}

}  // namespace

TEST(FeatureServer, UploadsAreStagedApartFromTheTablesInForce) {
  FeatureServer s(identity(), &store, apply, &app);
  s.boot(default_device_config());
  static lumavel::EdgeOffsetQ15 a[kMaxLensEdges], b[kMaxLensEdges];
  table(a, 80, 900);
  table(b, 80, -500);
  CHECK_TRUE(upload(s, 0, a, 81));
  CHECK_TRUE(set(s, with_lens(kLensCam0, a, nullptr)));
  CHECK_EQUAL(0, s.info().staged);
  // The host goes away two pieces into table b.
  CHECK_TRUE(upload(s, 0, b, 48));
  CHECK_EQUAL(1, s.info().staged);        // info says an upload is pending ...
  CHECK_EQUAL(0, s.info().config_status); // ... and that the last set was accepted: both true
  CHECK_EQUAL(0, s.info().lens_status);
  // A get reads the tables in force: complete, and the ones lens_crc names.
  for (uint8_t first = 0; first < 81; first += 24) {
    const LensChunk p = read_piece(s, 0, first);
    CHECK_EQUAL(first + 24 <= 81 ? 24 : 81 - first, p.count);
    MEMCMP_EQUAL(a + first, p.offsets, p.count * sizeof a[0]);
  }
}

TEST(FeatureServer, AnUploadNeverAppliedIsNotTakenByAnUnrelatedSet) {
  FeatureServer s(identity(), &store, apply, &app);
  s.boot(default_device_config());
  static lumavel::EdgeOffsetQ15 a[kMaxLensEdges], b[kMaxLensEdges];
  table(a, 80, 900);
  table(b, 80, -500);
  CHECK_TRUE(upload(s, 0, a, 81));
  CHECK_TRUE(set(s, with_lens(kLensCam0, a, nullptr)));
  // Table b uploaded completely, but its configuration never arrives.
  CHECK_TRUE(upload(s, 0, b, 81));
  // An unrelated set (another tau, the table in force by its CRC): b stays out.
  DeviceConfig c = with_lens(kLensCam0, a, nullptr);
  c.tau_us = 150000;
  CHECK_TRUE(set(s, c));
  MEMCMP_EQUAL(a, app.lens[0], 81 * sizeof a[0]);
  MEMCMP_EQUAL(a, s.lens().offsets[0], 81 * sizeof a[0]);
  CHECK_EQUAL(0, s.info().staged);  // the set ended the upload
  // Nor by a set naming b's CRC later: the staging was cleared.
  CHECK_FALSE(set(s, with_lens(kLensCam0, b, nullptr)));
  CHECK_EQUAL(static_cast<int>(ConfigField::kLens), s.info().config_status);
  MEMCMP_EQUAL(a, s.lens().offsets[0], 81 * sizeof a[0]);
  // Stored: the configuration in force with table a.
  App app2;
  FeatureServer s2(identity(), &store, apply, &app2);
  CHECK_TRUE(ConfigField::kOk == s2.boot(default_device_config()));
  CHECK_EQUAL(150000u, s2.config().tau_us);
  MEMCMP_EQUAL(a, app2.lens[0], 81 * sizeof a[0]);
}

TEST(FeatureServer, ASetTakesTheStagedTablesItsCrcNamesAndKeepsTheOthersInForce) {
  FeatureServer s(identity(), &store, apply, &app);
  s.boot(default_device_config());
  static lumavel::EdgeOffsetQ15 a[kMaxLensEdges], b[kMaxLensEdges], c1[kMaxLensEdges];
  table(a, 80, 900);
  table(b, 80, -500);
  table(c1, 80, 300);
  CHECK_TRUE(upload(s, 0, a, 81));
  CHECK_TRUE(upload(s, 1, c1, 81));
  CHECK_TRUE(set(s, with_lens(kLensCam0 | kLensCam1, a, c1)));
  // Only camera 0's table changes: b staged, camera 1's stays the one in force.
  CHECK_TRUE(upload(s, 0, b, 81));
  CHECK_TRUE(set(s, with_lens(kLensCam0 | kLensCam1, b, c1)));
  MEMCMP_EQUAL(b, app.lens[0], 81 * sizeof b[0]);
  MEMCMP_EQUAL(c1, app.lens[1], 81 * sizeof c1[0]);
  MEMCMP_EQUAL(b, s.lens().offsets[0], 81 * sizeof b[0]);
  // Dropping camera 1's table: the in-force area holds only what is named.
  CHECK_TRUE(set(s, with_lens(kLensCam0, b, nullptr)));
  CHECK_EQUAL(0, s.lens().filled[1]);
  CHECK_EQUAL(0, read_piece(s, 1, 0).count);
}

TEST(FeatureServer, ABrokenUploadLeavesTheRepairingSetWorking) {
  FeatureServer s(identity(), &store, apply, &app);
  s.boot(default_device_config());
  static lumavel::EdgeOffsetQ15 a[kMaxLensEdges], b[kMaxLensEdges];
  table(a, 80, 900);
  table(b, 80, -500);
  CHECK_TRUE(upload(s, 0, a, 81));
  CHECK_TRUE(set(s, with_lens(kLensCam0, a, nullptr)));
  // Piece 2 of b lost in transit: piece 3 arrives out of order and is refused.
  CHECK_TRUE(upload(s, 0, b, 24));
  LensChunk p{};
  p.camera = 0;
  p.first = 48;
  p.count = 24;
  for (int i = 0; i < 24; ++i) p.offsets[i] = b[48 + i];
  uint8_t buf[kLensChunkSize];
  encode_lens_chunk(p, buf, sizeof buf);
  CHECK_EQUAL(0u, FeatureServer::handle(&s, kReportLens, true, buf, sizeof buf, sizeof buf));
  CHECK_EQUAL(static_cast<int>(ConfigField::kLens), s.info().lens_status);
  CHECK_EQUAL(0, s.info().config_status);
  // b's configuration is refused (incomplete), saying so; a stays in force.
  CHECK_FALSE(set(s, with_lens(kLensCam0, b, nullptr)));
  CHECK_EQUAL(static_cast<int>(ConfigField::kLens), s.info().config_status);
  MEMCMP_EQUAL(a, s.lens().offsets[0], 81 * sizeof a[0]);
  // The repair: everything again, from piece 0.
  CHECK_TRUE(upload(s, 0, b, 81));
  CHECK_TRUE(set(s, with_lens(kLensCam0, b, nullptr)));
  CHECK_EQUAL(0, s.info().config_status);
  CHECK_EQUAL(0, s.info().lens_status);
  MEMCMP_EQUAL(b, app.lens[0], 81 * sizeof b[0]);
}
