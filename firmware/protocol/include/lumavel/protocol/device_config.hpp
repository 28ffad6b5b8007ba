// The user-facing device configuration (feature report 0x03, and the blob kept
// in the HAL's ConfigStore: the same bytes). Physical quantities in the named
// fixed-point formats of lumavel/units/fixed.hpp; integer only.
//
// Flow on the device: decode_config() (CRC, version) -> validate() (ranges) ->
// app::to_estimator_config() -> Estimator::configure() (the core's own checks)
// -> ConfigStore::save(encoded bytes). Nothing is applied unless all pass.
#pragma once
#include <cstddef>
#include <cstdint>

#include "lumavel/core/config.hpp"  // the estimator's option bits only (header, no link)
#include "lumavel/units/config_fields.hpp"
#include "lumavel/units/fixed.hpp"
#include "lumavel/protocol/lens.hpp"
#include "lumavel/protocol/reports.hpp"

namespace lumavel::protocol {

constexpr uint8_t kConfigVersion = 2;
// Kernel slots on the wire: fixed so that the layout does not depend on the
// build's LUMAVEL_MAX_KERNELS (validate() refuses counts above kMaxKernels).
constexpr int kWireKernels = 6;

// Orientation bits.
enum Orientation : uint8_t {
  kLooksRight = 1u << 0,      // optical axes point to the body's right (-y); else left (+y)
  kCam0UpsideDown = 1u << 1,  // cam0 mounted upside down (its u_sign becomes +1)
  kCam1UpsideDown = 1u << 2,
};
constexpr uint8_t kKnownOrientationBits = 0x07u;
static_assert(kKnownOrientationBits == (kLooksRight | kCam0UpsideDown | kCam1UpsideDown), "every Orientation bit");

// Lens bits: which cameras have a lens table (uploaded with report 0x05).
enum LensBits : uint8_t {
  kLensCam0 = 1u << 0,
  kLensCam1 = 1u << 1,
};
constexpr uint8_t kKnownLensBits = 0x03u;
static_assert(kKnownLensBits == (kLensCam0 | kLensCam1), "every LensBits bit");
// Estimator option bits the configuration may carry (lumavel/core/config.hpp).
constexpr uint8_t kKnownOptionBits = kKnownOptions;

struct KernelSetting {
  uint8_t order;   // 0..kMaxKernelOrder
  AngleQ28 sigma;  // rad
};

struct DeviceConfig {
  uint16_t width;           // working columns, kMinColumns..kMaxColumns
  uint16_t height;          // working rows, 1..kMaxRows
  // Ranges: lumavel/units/config_fields.hpp (the core's too); width-relative ones here.
  LengthQ24 baseline;       // h, m: x of cam1's optical centre minus cam0's, |h| in [1 mm, 1 m]
  AngleQ28 misalignment;    // yaw from cam0 to cam1, rad, |dtheta| <= 0.35
  PixelQ16 fu[2];           // focal length per camera, working pixels, [1, 8 * width]
  PixelQ16 cu[2];           // principal point column, working pixels, [0, width - 1]
  uint8_t orientation;      // Orientation bits
  AngleQ28 normaliser_sigma;  // order-0 window, rad, [0.5, 45] deg
  uint8_t kernel_count;     // 1..min(kWireKernels, kMaxKernels)
  KernelSetting kernels[kWireKernels];  // slots >= kernel_count must be zero
  uint32_t tau_us;          // observer time constant (gain 1/tau), [1 ms, 10 s]
  uint32_t frame_period_us; // nominal frame interval, [1 ms, 1 s]
  uint32_t max_gap_us;      // [frame_period_us, 4 s]
  uint32_t gyro_gap_us;     // [100 us, 1 s]
  ValueQ28 low_texture;     // [0, 1]
  uint16_t saturated_permille;  // 0..1000
  uint8_t options;          // estimator ConfigOption bits (kKnownOptionBits)
  LengthQ24 still_distance; // image change below which the rig counts as still, m, [0.1 mm, 10 cm]
  uint32_t still_min_us;    // stillness before the gyro offset is taken, [0.1 s, 60 s]
  uint8_t lens;             // LensBits: cameras with a lens table
  uint16_t lens_crc;        // lens_crc() of those tables (width + 1 edges each); 0 without
};

// Which field of a DeviceConfig was refused (travels in DeviceInfo.config_status).
enum class ConfigField : uint8_t {
  kOk = 0,
  kWidth,
  kHeight,
  kBaseline,
  kMisalignment,
  kFocalLength,
  kPrincipalPoint,
  kOrientation,
  kNormaliserSigma,
  kKernelCount,
  kKernelOrder,
  kKernelSigma,
  kTau,
  kFramePeriod,
  kMaxGap,
  kGyroGap,
  kLowTexture,
  kSaturatedPermille,
  kOptions,
  kStillDistance,
  kStillDuration,
  kLens,       // unknown lens bits, lens_crc set without tables, or a table incomplete / not matching lens_crc
  kLensEdges,  // the estimator refused a lens table (edges not monotonic or outside [-pi, pi])
  kMalformed,  // the report itself was refused (length, id, version, CRC)
  kEstimator,  // passed these ranges but the estimator refused it (e.g. kernel outside the view)
  kStore,      // accepted but could not be persisted
};
// DeviceInfo carries a ConfigField in config_status; its decoder's bound must follow the list.
static_assert(kMaxConfigStatus == static_cast<uint8_t>(ConfigField::kStore), "kMaxConfigStatus is the last ConfigField");
const char* to_string(ConfigField f);
// The range validate() holds the field to, in the units of the configuration
// text (m, rad, px, us), e.g. "baseline |h| must be 0.001..1 m".
const char* rule_of(ConfigField f);

// First field out of range, kOk if none.
ConfigField validate(const DeviceConfig& c);

// Feature report 0x03 layout (little-endian):
//   off size field
//   0   1    id = 0x03
//   1   1    config version (kConfigVersion)
//   2   2    width            4   2  height
//   6   4    baseline         10  4  misalignment
//   14  4    fu[0]            18  4  cu[0]
//   22  4    fu[1]            26  4  cu[1]
//   30  1    orientation      31  4  normaliser_sigma
//   35  1    kernel_count     36  30 kernels[6] {order u8, sigma i32}
//   66  4    tau_us           70  4  frame_period_us
//   74  4    max_gap_us       78  4  gyro_gap_us
//   82  4    low_texture      86  2  saturated_permille
//   88  1    options          89  4  still_distance (LengthQ24)
//   93  4    still_min_us     97  1  lens (LensBits)
//   98  2    lens_crc
//   100 2    crc16 of bytes 0..99
size_t encode_config(const DeviceConfig& c, uint8_t* buf, size_t cap);
// Checks length, ID, version and CRC, then validate(): on kOutOfRange,
// result.field names the field (to_string(ConfigField)).
DecodeResult decode_config(const uint8_t* buf, size_t len, DeviceConfig& out);
// The same checks, the outcome as a ConfigField: kMalformed for length, ID,
// version or CRC, else the first field out of range (kOk: out is set).
ConfigField parse_config(const uint8_t* buf, size_t len, DeviceConfig& out);

// The blob kept in the ConfigStore: the configuration report (kConfigSize
// bytes) followed by the lens tables it names (camera 0 first, width + 1
// little-endian i16 each). Its length follows from the configuration.
constexpr size_t kMaxStoredConfigSize = kConfigSize + 2 * 2 * kMaxLensEdges;
size_t stored_config_size(const DeviceConfig& c);
// 0 if cap is too small or c names a table that `lens` does not fill.
size_t encode_stored_config(const DeviceConfig& c, const LensTables& lens, uint8_t* buf, size_t cap);
// kMalformed for a bad report or a length that does not match; kLens when
// the tables do not match lens_crc; else validate()'s outcome. On kOk, c and
// the named tables of lens (filled = width + 1) are set; lens.filled is 0
// for the others, and for both after a failure past the header.
ConfigField decode_stored_config(const uint8_t* buf, size_t len, DeviceConfig& c, LensTables& lens);

// The one default geometry for a resolution: the defaults of
// config_fields.hpp (8 cm rig looking left, the default kernel bank sized to fov) at
// width x height, fu for the field of view `fov` at that width, cu the
// centre column. Firmware passes a constexpr FieldOfView only.
DeviceConfig defaults_for(uint16_t width, uint16_t height, config::FieldOfView fov = config::kDefaultFov);
// defaults_for(40, 30): what a device runs when its store is empty or invalid.
DeviceConfig default_device_config();

}  // namespace lumavel::protocol
