// libFuzzer targets for the report and configuration parsers. Built twice
// (LUMAVEL_FUZZ_CONFIG selects the target: configuration report and the
// stored blob with its lens tables; else measurement, info, mailbox, lens piece). Besides "never crash", each
// checks a property: whatever decodes re-encodes to the same bytes. The input
// is also tried with its CRC repaired, so that the range checks behind the
// CRC get fuzzed too.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>

#include "lumavel/app/estimator_config.hpp"
#include "lumavel/protocol/crc.hpp"
#include "lumavel/protocol/device_config.hpp"
#include "lumavel/protocol/lens.hpp"
#include "lumavel/protocol/reports.hpp"

using namespace lumavel::protocol;
using lumavel::app::to_estimator_config;

namespace {

void require(bool ok) {
  if (!ok) std::abort();
}

// Copies at most `size` bytes and rewrites the trailing CRC when it fits.
size_t resealed(const uint8_t* in, size_t len, size_t size, uint8_t* out) {
  const size_t n = len < size ? len : size;
  std::memcpy(out, in, n);
  if (n == size) {
    const uint16_t c = crc16(out, size - 2);
    out[size - 2] = static_cast<uint8_t>(c);
    out[size - 1] = static_cast<uint8_t>(c >> 8);
  }
  return n;
}

#ifdef LUMAVEL_FUZZ_CONFIG
void one(const uint8_t* data, size_t len) {
  DeviceConfig c{};
  if (decode_config(data, len, c).ok()) {
    require(validate(c) == ConfigField::kOk);
    uint8_t again[kConfigSize];
    require(encode_config(c, again, sizeof again) == kConfigSize);
    require(std::memcmp(again, data, kConfigSize) == 0);
    lumavel::EstimatorConfig e{};
    static const lumavel::EdgeOffsetQ15 none[kMaxLensEdges] = {};
    const lumavel::EdgeOffsetQ15* const lens[2] = {none, none};
    require(to_estimator_config(c, e, lens));
  }
  // The stored blob: whatever decodes re-encodes to the same bytes.
  static LensTables t;
  DeviceConfig s{};
  if (decode_stored_config(data, len, s, t) == ConfigField::kOk) {
    static uint8_t again[kMaxStoredConfigSize];
    require(encode_stored_config(s, t, again, sizeof again) == len);
    require(std::memcmp(again, data, len) == 0);
  }
}
void fuzz(const uint8_t* data, size_t len) {
  one(data, len);
  static uint8_t buf[kMaxStoredConfigSize];
  const size_t n = resealed(data, len, kConfigSize, buf);
  // Keep the tail so that blobs with tables get past the header's CRC.
  if (len > kConfigSize) std::memcpy(buf + kConfigSize, data + kConfigSize, len - kConfigSize < sizeof buf - kConfigSize ? len - kConfigSize : sizeof buf - kConfigSize);
  one(buf, len > kConfigSize ? (len < sizeof buf ? len : sizeof buf) : n);
}
#else
void one(const uint8_t* data, size_t len) {
  uint8_t again[kMaxReportSize];
  Measurement m{};
  if (decode_measurement(data, len, m).ok()) {
    require(encode_measurement(m, again, sizeof again) == kMeasurementSize);
    require(std::memcmp(again, data, kMeasurementSize) == 0);
  }
  DeviceInfo d{};
  if (decode_device_info(data, len, d).ok()) {
    require(encode_device_info(d, again, sizeof again) == kDeviceInfoSize);
    require(std::memcmp(again, data, kDeviceInfoSize) == 0);
  }
  FeatureChunk c{};
  if (decode_feature_chunk(data, len, c).ok()) {
    require(encode_feature_chunk(c, again, sizeof again) == kFeatureChunkSize);
    require(std::memcmp(again, data, kFeatureChunkSize) == 0);
  }
  LensChunk l{};
  if (decode_lens_chunk(data, len, l).ok()) {
    require(encode_lens_chunk(l, again, sizeof again) == kLensChunkSize);
    require(std::memcmp(again, data, kLensChunkSize) == 0);
  }
  uint8_t id = 0, tag = 0;
  if (decode_mailbox_request(data, len, id, tag).ok()) {
    require(encode_mailbox_request(id, tag, again, sizeof again) == kMailboxSize);
    require(std::memcmp(again, data, kMailboxSize) == 0);
  }
}
void fuzz(const uint8_t* data, size_t len) {
  one(data, len);
  uint8_t buf[kMaxReportSize];
  one(buf, resealed(data, len, kMeasurementSize, buf));
  one(buf, resealed(data, len, kDeviceInfoSize, buf));
  one(buf, resealed(data, len, kLensChunkSize, buf));
}
#endif

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t len) {
  fuzz(data, len);
  return 0;
}
