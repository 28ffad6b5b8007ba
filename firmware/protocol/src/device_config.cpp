#include "lumavel/protocol/device_config.hpp"

#include "lumavel/units/config_fields.hpp"
#include "lumavel/units/limits.hpp"
#include "frame.hpp"
#include "wire.hpp"

namespace lumavel::protocol {

using namespace wire;

namespace {

// The ranges: lumavel/units/config_fields.hpp, the core's too (a value
// accepted here is one Estimator::configure() takes range-wise).
using config::Quantity;
using config::range;
constexpr int64_t kOneQ16 = int64_t{1} << fx::kPixelFrac;
constexpr size_t kKernelOffset = 36;
constexpr size_t kKernelStride = 5;
static_assert(config::kDefaultKernelCount <= kWireKernels, "the default bank travels on the wire");

bool in(int64_t v, int64_t lo, int64_t hi) { return v >= lo && v <= hi; }

}  // namespace

const char* to_string(ConfigField f) {
  switch (f) {
    case ConfigField::kOk: return "ok";
    case ConfigField::kWidth: return "width";
    case ConfigField::kHeight: return "height";
    case ConfigField::kBaseline: return "baseline";
    case ConfigField::kMisalignment: return "misalignment";
    case ConfigField::kFocalLength: return "fu";
    case ConfigField::kPrincipalPoint: return "cu";
    case ConfigField::kOrientation: return "orientation";
    case ConfigField::kNormaliserSigma: return "normaliser_sigma";
    case ConfigField::kKernelCount: return "kernel_count";
    case ConfigField::kKernelOrder: return "kernel_order";
    case ConfigField::kKernelSigma: return "kernel_sigma";
    case ConfigField::kTau: return "tau_us";
    case ConfigField::kFramePeriod: return "frame_period_us";
    case ConfigField::kMaxGap: return "max_gap_us";
    case ConfigField::kGyroGap: return "gyro_gap_us";
    case ConfigField::kLowTexture: return "low_texture";
    case ConfigField::kSaturatedPermille: return "saturated_permille";
    case ConfigField::kOptions: return "options";
    case ConfigField::kStillDistance: return "still_distance";
    case ConfigField::kStillDuration: return "still_min_us";
    case ConfigField::kLens: return "lens";
    case ConfigField::kLensEdges: return "lens edges";
    case ConfigField::kMalformed: return "malformed report";
    case ConfigField::kEstimator: return "refused by the estimator";
    case ConfigField::kStore: return "could not be stored";
  }
  return "unknown";
}

#define LUMAVEL_TEXT2(x) #x
#define LUMAVEL_TEXT(x) LUMAVEL_TEXT2(x)

// The ranges of config_fields.hpp in words (the text is checked by tests): change one, change the other.
const char* rule_of(ConfigField f) {
  switch (f) {
    case ConfigField::kOk: return "ok";
    case ConfigField::kWidth: return "width must be 16.." LUMAVEL_TEXT(LUMAVEL_MAX_COLS) " columns";
    case ConfigField::kHeight: return "height must be 1.." LUMAVEL_TEXT(LUMAVEL_MAX_ROWS) " rows";
    case ConfigField::kBaseline: return "baseline |h| must be 0.001..1 m";
    case ConfigField::kMisalignment: return "misalignment must be -0.35..0.35 rad";
    case ConfigField::kFocalLength: return "fu must be 1..8 * width px";
    case ConfigField::kPrincipalPoint: return "cu must be 0..width - 1 px";
    case ConfigField::kOrientation: return "unknown orientation bits";
    case ConfigField::kNormaliserSigma: return "normaliser sigma must be 0.00873..0.785 rad (0.5..45 deg)";
    case ConfigField::kKernelCount: return "kernels must list 1..min(6, LUMAVEL_MAX_KERNELS) kernels";
    case ConfigField::kKernelOrder: return "kernel orders must be 0..3";
    case ConfigField::kKernelSigma: return "kernel sigmas must be 0.00873..0.785 rad (0.5..45 deg)";
    case ConfigField::kTau: return "tau_us must be 1000..10000000 us";
    case ConfigField::kFramePeriod: return "frame_period_us must be 1000..1000000 us";
    case ConfigField::kMaxGap: return "max_gap_us must be frame_period_us..4000000 us";
    case ConfigField::kGyroGap: return "gyro_gap_us must be 100..1000000 us";
    case ConfigField::kLowTexture: return "low_texture must be 0..1";
    case ConfigField::kSaturatedPermille: return "saturated_permille must be 0..1000";
    case ConfigField::kOptions: return "unknown option bits";
    case ConfigField::kStillDistance: return "still_distance_m must be 0.0001..0.1 m";
    case ConfigField::kStillDuration: return "still_min_us must be 100000..60000000 us";
    case ConfigField::kLens: return "a lens table must have width + 1 values";
    case ConfigField::kLensEdges: return "lens column edges must be monotonic and within [-pi, pi]";
    case ConfigField::kMalformed: return "the report was malformed";
    case ConfigField::kEstimator: return "the estimator refused it (e.g. a kernel outside the view)";
    case ConfigField::kStore: return "it could not be stored";
  }
  return "unknown";
}

#undef LUMAVEL_TEXT
#undef LUMAVEL_TEXT2

ConfigField validate(const DeviceConfig& c) {
  if (!in(c.width, kMinColumns, kMaxColumns)) return ConfigField::kWidth;
  if (!in(c.height, 1, kMaxRows)) return ConfigField::kHeight;
  const int64_t h = c.baseline < 0 ? -int64_t{c.baseline} : int64_t{c.baseline};
  if (!range<Quantity::kBaseline>.holds(h)) return ConfigField::kBaseline;
  if (!range<Quantity::kMisalignment>.holds(c.misalignment)) return ConfigField::kMisalignment;
  for (int i = 0; i < 2; ++i) {
    // 8 x width (a field of view >= 7 degrees) is inside the core's range (config_fields.hpp).
    if (!in(c.fu[i], range<Quantity::kFocalLength>.lo, 8 * kOneQ16 * c.width)) return ConfigField::kFocalLength;
    if (!in(c.cu[i], 0, kOneQ16 * (c.width - 1))) return ConfigField::kPrincipalPoint;
  }
  if ((c.orientation & ~kKnownOrientationBits) != 0) return ConfigField::kOrientation;
  if (!range<Quantity::kKernelSigma>.holds(c.normaliser_sigma)) return ConfigField::kNormaliserSigma;
  const int max_count = kMaxKernels < kWireKernels ? kMaxKernels : kWireKernels;
  if (!in(c.kernel_count, 1, max_count)) return ConfigField::kKernelCount;
  for (int i = 0; i < kWireKernels; ++i) {
    const KernelSetting& k = c.kernels[i];
    if (i >= c.kernel_count) {
      // Unused slots are zero so that a configuration has one encoding.
      if (k.order != 0) return ConfigField::kKernelOrder;
      if (k.sigma != 0) return ConfigField::kKernelSigma;
      continue;
    }
    if (k.order > kMaxKernelOrder) return ConfigField::kKernelOrder;
    if (!range<Quantity::kKernelSigma>.holds(k.sigma)) return ConfigField::kKernelSigma;
  }
  if (!range<Quantity::kTau>.holds(c.tau_us)) return ConfigField::kTau;
  if (!range<Quantity::kFramePeriod>.holds(c.frame_period_us)) return ConfigField::kFramePeriod;
  if (!in(c.max_gap_us, c.frame_period_us, range<Quantity::kMaxGap>.hi)) return ConfigField::kMaxGap;
  if (!range<Quantity::kGyroGap>.holds(c.gyro_gap_us)) return ConfigField::kGyroGap;
  if (!range<Quantity::kLowTexture>.holds(c.low_texture)) return ConfigField::kLowTexture;
  if (!range<Quantity::kSaturatedPermille>.holds(c.saturated_permille)) return ConfigField::kSaturatedPermille;
  if ((c.options & ~kKnownOptionBits) != 0) return ConfigField::kOptions;
  if (!range<Quantity::kStillDistance>.holds(c.still_distance)) return ConfigField::kStillDistance;
  if (!range<Quantity::kStillDuration>.holds(c.still_min_us)) return ConfigField::kStillDuration;
  if ((c.lens & ~kKnownLensBits) != 0 || (c.lens == 0 && c.lens_crc != 0)) return ConfigField::kLens;
  return ConfigField::kOk;
}

size_t encode_config(const DeviceConfig& c, uint8_t* buf, size_t cap) {
  if (buf == nullptr || cap < kConfigSize) return 0;
  put_u8(buf, 0, kReportConfig);
  put_u8(buf, 1, kConfigVersion);
  put_u16(buf, 2, c.width);
  put_u16(buf, 4, c.height);
  put_i32(buf, 6, c.baseline);
  put_i32(buf, 10, c.misalignment);
  put_i32(buf, 14, c.fu[0]);
  put_i32(buf, 18, c.cu[0]);
  put_i32(buf, 22, c.fu[1]);
  put_i32(buf, 26, c.cu[1]);
  put_u8(buf, 30, c.orientation);
  put_i32(buf, 31, c.normaliser_sigma);
  put_u8(buf, 35, c.kernel_count);
  for (int i = 0; i < kWireKernels; ++i) {
    const size_t off = kKernelOffset + kKernelStride * static_cast<size_t>(i);
    put_u8(buf, off, c.kernels[i].order);
    put_i32(buf, off + 1, c.kernels[i].sigma);
  }
  put_u32(buf, 66, c.tau_us);
  put_u32(buf, 70, c.frame_period_us);
  put_u32(buf, 74, c.max_gap_us);
  put_u32(buf, 78, c.gyro_gap_us);
  put_i32(buf, 82, c.low_texture);
  put_u16(buf, 86, c.saturated_permille);
  put_u8(buf, 88, c.options);
  put_i32(buf, 89, c.still_distance);
  put_u32(buf, 93, c.still_min_us);
  put_u8(buf, 97, c.lens);
  put_u16(buf, 98, c.lens_crc);
  frame::seal(buf, kConfigSize);
  return kConfigSize;
}

namespace {

ReportError check_frame(const uint8_t* buf, size_t len) {
  return frame::check(buf, len, kReportConfig, kConfigVersion, kConfigSize, true).error;
}

DeviceConfig unpack(const uint8_t* buf) {
  DeviceConfig c{};
  c.width = get_u16(buf, 2);
  c.height = get_u16(buf, 4);
  c.baseline = get_i32(buf, 6);
  c.misalignment = get_i32(buf, 10);
  c.fu[0] = get_i32(buf, 14);
  c.cu[0] = get_i32(buf, 18);
  c.fu[1] = get_i32(buf, 22);
  c.cu[1] = get_i32(buf, 26);
  c.orientation = buf[30];
  c.normaliser_sigma = get_i32(buf, 31);
  c.kernel_count = buf[35];
  for (int i = 0; i < kWireKernels; ++i) {
    const size_t off = kKernelOffset + kKernelStride * static_cast<size_t>(i);
    c.kernels[i].order = buf[off];
    c.kernels[i].sigma = get_i32(buf, off + 1);
  }
  c.tau_us = get_u32(buf, 66);
  c.frame_period_us = get_u32(buf, 70);
  c.max_gap_us = get_u32(buf, 74);
  c.gyro_gap_us = get_u32(buf, 78);
  c.low_texture = get_i32(buf, 82);
  c.saturated_permille = get_u16(buf, 86);
  c.options = buf[88];
  c.still_distance = get_i32(buf, 89);
  c.still_min_us = get_u32(buf, 93);
  c.lens = buf[97];
  c.lens_crc = get_u16(buf, 98);
  return c;
}

}  // namespace

DecodeResult decode_config(const uint8_t* buf, size_t len, DeviceConfig& out) {
  const ReportError e = check_frame(buf, len);
  if (e != ReportError::kOk) return DecodeResult{e, ""};
  const DeviceConfig c = unpack(buf);
  const ConfigField f = validate(c);
  if (f != ConfigField::kOk) return DecodeResult{ReportError::kOutOfRange, to_string(f)};
  out = c;
  return DecodeResult{ReportError::kOk, ""};
}

ConfigField parse_config(const uint8_t* buf, size_t len, DeviceConfig& out) {
  if (check_frame(buf, len) != ReportError::kOk) return ConfigField::kMalformed;
  const DeviceConfig c = unpack(buf);
  const ConfigField f = validate(c);
  if (f == ConfigField::kOk) out = c;
  return f;
}

DeviceConfig defaults_for(uint16_t width, uint16_t height, config::FieldOfView fov) {
  DeviceConfig c{};
  c.width = width;
  c.height = height;
  c.baseline = static_cast<LengthQ24>(config::default_of<Quantity::kBaseline>);
  c.misalignment = static_cast<AngleQ28>(config::default_of<Quantity::kMisalignment>);
  for (int i = 0; i < 2; ++i) {
    // The same field of view at this width (rounded down, as the boards have always had it).
    c.fu[i] = static_cast<PixelQ16>(int64_t{fov.fu_at_default_width} * width / kDefaultColumns);
    c.cu[i] = static_cast<PixelQ16>((int32_t{width} - 1) * (kOneQ16 / 2));  // the centre column
  }
  c.orientation = 0;  // looking left, upright
  c.normaliser_sigma = static_cast<AngleQ28>(config::default_of<Quantity::kKernelSigma>);
  c.kernel_count = static_cast<uint8_t>(config::kDefaultKernelsBuilt);
  for (int k = 0; k < config::kDefaultKernelsBuilt; ++k)
    c.kernels[k] = KernelSetting{static_cast<uint8_t>(config::kDefaultKernels[k].order), fov.kernel_sigma[k]};
  c.tau_us = static_cast<uint32_t>(config::default_of<Quantity::kTau>);
  c.frame_period_us = static_cast<uint32_t>(config::default_of<Quantity::kFramePeriod>);
  c.max_gap_us = static_cast<uint32_t>(config::default_of<Quantity::kMaxGap>);
  c.gyro_gap_us = static_cast<uint32_t>(config::default_of<Quantity::kGyroGap>);
  c.low_texture = static_cast<ValueQ28>(config::default_of<Quantity::kLowTexture>);
  c.saturated_permille = static_cast<uint16_t>(config::default_of<Quantity::kSaturatedPermille>);
  // The estimator's defaults: finite-baseline correction and gyro-offset
  // learning on, stillness judged over 2 mm and 0.5 s (gyro_offset.hpp).
  // the balance off (settings.hpp); the match where it is built in
  // and the elevation band for wide views (config::kElevationBandMinHfovRad).
  c.options = static_cast<uint8_t>(kOptionBaselineCorrection | kOptionGyroOffsetLearning |
                                   (kHavePhotometricMatch ? kOptionPhotometricMatch : 0) |
                                   (fov.elevation_band ? kOptionElevationBand : 0));
  c.still_distance = static_cast<LengthQ24>(config::default_of<Quantity::kStillDistance>);
  c.still_min_us = static_cast<uint32_t>(config::default_of<Quantity::kStillDuration>);
  c.lens = 0;  // pinhole
  c.lens_crc = 0;
  return c;
}

DeviceConfig default_device_config() {
  return defaults_for(static_cast<uint16_t>(kDefaultColumns), static_cast<uint16_t>(kDefaultRows));
}

size_t stored_config_size(const DeviceConfig& c) {
  const size_t tables = ((c.lens & kLensCam0) ? 1u : 0u) + ((c.lens & kLensCam1) ? 1u : 0u);
  return kConfigSize + tables * 2 * (size_t{c.width} + 1);
}

size_t encode_stored_config(const DeviceConfig& c, const LensTables& lens, uint8_t* buf, size_t cap) {
  const size_t n = stored_config_size(c);
  if (n > cap || c.width + 1u > kMaxLensEdges) return 0;
  if (encode_config(c, buf, cap) != kConfigSize) return 0;
  size_t off = kConfigSize;
  for (int cam = 0; cam < 2; ++cam) {
    if ((c.lens & (1u << cam)) == 0) continue;
    if (lens.filled[cam] != c.width + 1u) return 0;
    for (uint16_t u = 0; u <= c.width; ++u, off += 2) put_i16(buf, off, lens.offsets[cam][u]);
  }
  return n;
}

ConfigField decode_stored_config(const uint8_t* buf, size_t len, DeviceConfig& c, LensTables& lens) {
  DeviceConfig d{};
  const ConfigField f = parse_config(buf, len < kConfigSize ? len : kConfigSize, d);
  if (f != ConfigField::kOk) return f;
  if (len != stored_config_size(d) || d.width + 1u > kMaxLensEdges) return ConfigField::kMalformed;
  // Straight into `lens` (no second copy of the tables on the stack).
  lens.filled[0] = lens.filled[1] = 0;
  size_t off = kConfigSize;
  for (int cam = 0; cam < 2; ++cam) {
    if ((d.lens & (1u << cam)) == 0) continue;
    for (uint16_t u = 0; u <= d.width; ++u, off += 2) lens.offsets[cam][u] = get_i16(buf, off);
    lens.filled[cam] = static_cast<uint16_t>(d.width + 1u);
  }
  const EdgeOffsetQ15* const tables[2] = {lens.offsets[0], lens.offsets[1]};
  if (lens_crc(tables, d.lens, static_cast<uint16_t>(d.width + 1u)) != d.lens_crc) {
    lens.filled[0] = lens.filled[1] = 0;
    return ConfigField::kLens;
  }
  c = d;
  return ConfigField::kOk;
}

}  // namespace lumavel::protocol
