// A lens configuration through the app's feature requests: the tables are
// uploaded in pieces (report 0x05), named by the configuration, applied to
// the estimator's kernel bank, persisted and readable back (GET and mailbox).
// The edges the device builds from its configuration and tables must equal
// the host's Q28 edge tables (to_fixed_edges) within half a step of the lens
// format, and its kernel tables must be those of an estimator configured
// with the host's tables directly (what `lumavel-sim run` does).
#include <CppUTest/TestHarness.h>

#include <cmath>
#include <algorithm>
#include <cstdint>
#include <memory>
#include <vector>

#include "app_env.hpp"
#include "fake_hal.hpp"
#include "lumavel/app/app.hpp"
#include "lumavel/app/estimator_config.hpp"
#include "lumavel/core/estimator.hpp"
#include "lumavel/host/settings.hpp"
#include "lumavel/protocol/device_config.hpp"
#include "lumavel/protocol/lens.hpp"

using lumavel::EdgeOffsetQ15;
using lumavel::app::App;
using lumavel::app::RunState;
namespace protocol = lumavel::protocol;
namespace host = lumavel::host;

namespace {

// Barrel-distorted edges (k1 = -0.14) of one camera of the device's
// default 40-column configuration, as the host derives them from sensor.yaml.
host::CameraModel barrel(const lumavel::CameraGeometry& g, double k1) {
  host::CameraModel m;
  m.fu = std::ldexp(g.fu, -16);
  m.cu = std::ldexp(g.cu, -16);
  m.axis_yaw = std::ldexp(g.axis_yaw, -28);
  m.u_sign = g.u_sign;
  for (int u = 0; u <= 40; ++u) {
    const double xd = (u - 0.5 - m.cu) / m.fu;
    double x = xd;
    for (int it = 0; it < 30; ++it) x = xd / (1 + k1 * x * x);
    m.edges.push_back(m.axis_yaw + m.u_sign * std::atan(x));
  }
  return m;
}

// Kernel tables of two banks are the same (every camera, kernel and column).
bool same_tables(const lumavel::KernelBank& a, const lumavel::KernelBank& b) {
  for (int i = 0; i < 2; ++i)
    for (int k = 0; k < a.count; ++k)
      for (int u = 0; u < a.width; ++u)
        if (a.cam[i].k[k].w[u] != b.cam[i].k[k].w[u] || a.cam[i].d[k].w[u] != b.cam[i].d[k].w[u] ||
            a.cam[i].k[k].exp != b.cam[i].k[k].exp)
          return false;
  return a.count == b.count && a.width == b.width;
}

std::vector<uint8_t> lens_piece(uint8_t cam, size_t first, const std::vector<EdgeOffsetQ15>& t, size_t count) {
  protocol::LensChunk c{};
  c.camera = cam;
  c.first = static_cast<uint8_t>(first);
  c.count = static_cast<uint8_t>(count);
  for (size_t i = 0; i < count; ++i) c.offsets[i] = t[first + i];
  std::vector<uint8_t> b(protocol::kLensChunkSize);
  protocol::encode_lens_chunk(c, b.data(), b.size());
  return b;
}

}  // namespace

TEST_GROUP(AppLens) {
  std::unique_ptr<Env> env;
  lumavel::EstimatorConfig fixed{};
  host::CameraModel model[2];
  std::vector<EdgeOffsetQ15> table[2];
  void setup() override {
    env = std::make_unique<Env>();
    for (uint64_t k = 1; k <= 40; ++k) env->camera.times.push_back(k * kPeriod);
    CHECK_TRUE(env->app.start());
    CHECK_TRUE(lumavel::app::to_estimator_config(protocol::default_device_config(), fixed));
    for (int i = 0; i < 2; ++i) {
      model[i] = barrel(fixed.cam[i], i == 0 ? -0.14 : -0.10);
      table[i] = host::to_fixed_edge_offsets(model[i], fixed.cam[i], 40);
    }
  }
  void teardown() override { env.reset(); }
  size_t request(uint8_t id, bool is_set, std::vector<uint8_t> data = {}) {
    env->link.pending.push_back({id, is_set, std::move(data)});
    CHECK_TRUE(RunState::kFrame == env->app.run_once());
    // A set answers {accepted}; a get answers the report.
    return is_set ? env->link.replies.back().at(0) : env->link.replies.back().size();
  }
  void upload(uint8_t cam, const std::vector<EdgeOffsetQ15>& t) {
    for (size_t first = 0; first < t.size(); first += protocol::kLensChunkEdges) {
      const size_t n = std::min(protocol::kLensChunkEdges, t.size() - first);
      CHECK_EQUAL(1u, request(protocol::kReportLens, true, lens_piece(cam, first, t, n)));
    }
  }
  protocol::DeviceConfig with_lens(uint8_t lens) {
    protocol::DeviceConfig c = protocol::default_device_config();
    c.lens = lens;
    const EdgeOffsetQ15* const t[2] = {table[0].data(), table[1].data()};
    c.lens_crc = protocol::lens_crc(t, lens, 41);
    return c;
  }
  std::vector<uint8_t> encoded(const protocol::DeviceConfig& c) {
    std::vector<uint8_t> b(protocol::kConfigSize);
    protocol::encode_config(c, b.data(), b.size());
    return b;
  }
};

TEST(AppLens, AppliedEdgesEqualTheHostsEdgeTables) {
  auto pinhole = std::make_unique<lumavel::Estimator>();
  CHECK_TRUE(lumavel::ConfigError::kOk == pinhole->configure(fixed));
  CHECK_TRUE(same_tables(pinhole->bank(), env->app.estimator().bank()));  // before: no lens
  upload(0, table[0]);
  upload(1, table[1]);
  CHECK_EQUAL(1u, request(protocol::kReportConfig, true, encoded(with_lens(protocol::kLensCam0 | protocol::kLensCam1))));
  // The edges from the device's geometry and its tables, against the host's.
  double worst = 0, moved = 0;
  for (int i = 0; i < 2; ++i) {
    const std::vector<lumavel::AngleQ28> want = host::to_fixed_edges(model[i], 40);
    lumavel::AngleQ28 pin[41], got[41];
    lumavel::pinhole_column_edges(env->app.estimator().config().cam[i], 40, pin);
    lumavel::column_edge_yaws(env->app.estimator().config().cam[i], env->app.lens_tables().offsets[i], 40, got);
    for (int u = 0; u <= 40; ++u) {
      worst = std::fmax(worst, std::fabs(static_cast<double>(got[u]) - want[static_cast<size_t>(u)]));
      moved = std::fmax(moved, std::fabs(static_cast<double>(got[u]) - pin[u]));
    }
  }
  // Half a Q15 step is 2^12 in Q28 (plus the host's own rounding of both).
  CHECK(worst <= 4097);
  CHECK(moved > 100 * 4096);  // the lens really moves the edges (0.02 rad at the sides)
  // The kernel tables are those of the host's fixed engine with the same tables.
  lumavel::EstimatorConfig with = fixed;
  with.edge_offsets[0] = table[0].data();
  with.edge_offsets[1] = table[1].data();
  auto reference = std::make_unique<lumavel::Estimator>();
  CHECK_TRUE(lumavel::ConfigError::kOk == reference->configure(with));
  CHECK_TRUE(same_tables(reference->bank(), env->app.estimator().bank()));
  CHECK_FALSE(same_tables(pinhole->bank(), env->app.estimator().bank()));
  // Persisted with the tables: the blob is the report plus 2 x 41 offsets.
  CHECK_EQUAL(protocol::kConfigSize + 2 * 41 * 2, env->store.blob.size());
}

TEST(AppLens, StoredLensIsAppliedAtBoot) {
  upload(1, table[1]);
  CHECK_EQUAL(1u, request(protocol::kReportConfig, true, encoded(with_lens(protocol::kLensCam1))));
  auto again = std::make_unique<Env>();
  again->store.blob = env->store.blob;
  again->camera.times = {kPeriod};
  CHECK_TRUE(again->app.start());
  CHECK_EQUAL(protocol::kConfigStored, again->app.config_source());
  CHECK_TRUE(same_tables(env->app.estimator().bank(), again->app.estimator().bank()));
}

TEST(AppLens, NonMonotonicTableIsRefusedAsLensEdges) {
  table[0][10] = static_cast<EdgeOffsetQ15>(table[0][10] + 3000);  // 0.09 rad: past its neighbour
  upload(0, table[0]);
  auto before = std::make_unique<lumavel::KernelBank>(env->app.estimator().bank());
  CHECK_EQUAL(0u, request(protocol::kReportConfig, true, encoded(with_lens(protocol::kLensCam0))));
  CHECK_EQUAL(static_cast<int>(protocol::ConfigField::kLensEdges), static_cast<int>(env->app.config_status()));
  CHECK_TRUE(same_tables(*before, env->app.estimator().bank()));
  CHECK_EQUAL(0, env->store.saves);
}

TEST(AppLens, IncompleteTableIsRefusedAsLens) {
  std::vector<EdgeOffsetQ15> part(table[0].begin(), table[0].begin() + 30);
  upload(0, part);
  CHECK_EQUAL(0u, request(protocol::kReportConfig, true, encoded(with_lens(protocol::kLensCam0))));
  CHECK_EQUAL(static_cast<int>(protocol::ConfigField::kLens), static_cast<int>(env->app.config_status()));
}

TEST(AppLens, TablesReadBackThroughGetAndMailbox) {
  upload(0, table[0]);
  CHECK_EQUAL(1u, request(protocol::kReportConfig, true, encoded(with_lens(protocol::kLensCam0))));
  // Select camera 0 from edge 24, then GET.
  CHECK_EQUAL(1u, request(protocol::kReportLens, true, lens_piece(0, 24, table[0], 0)));
  CHECK_EQUAL(protocol::kLensChunkSize, request(protocol::kReportLens, false));
  protocol::LensChunk got{};
  const std::vector<uint8_t>& r = env->link.replies.back();
  CHECK_TRUE(protocol::decode_lens_chunk(r.data(), r.size(), got).ok());
  CHECK_EQUAL(17, got.count);  // edges 24..40
  for (int i = 0; i < 17; ++i) CHECK_EQUAL(table[0][static_cast<size_t>(24 + i)], got.offsets[i]);
  // The same piece through the mailbox (one 0x84 chunk).
  std::vector<uint8_t> m(protocol::kMailboxSize);
  protocol::encode_mailbox_request(protocol::kReportLens, 1, m.data(), m.size());
  env->link.inputs.clear();
  CHECK_EQUAL(1u, request(protocol::kReportMailbox, true, m));
  size_t chunks = 0;
  for (const auto& in : env->link.inputs) {
    if (in[0] != protocol::kReportFeatureChunk) continue;
    protocol::FeatureChunk c{};
    CHECK_TRUE(protocol::decode_feature_chunk(in.data(), in.size(), c).ok());
    CHECK_EQUAL(protocol::kLensChunkSize, c.total);
    protocol::LensChunk via{};
    CHECK_TRUE(protocol::decode_lens_chunk(c.data, c.length, via).ok());
    CHECK_EQUAL(got.count, via.count);
    ++chunks;
  }
  CHECK_EQUAL(1u, chunks);
}
