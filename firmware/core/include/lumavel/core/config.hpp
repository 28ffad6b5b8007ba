// The estimator's configuration: plain data, validated before use.
// The host (or the HID configuration report) fills it; nothing here does I/O.
#pragma once
#include <cstdint>

#include "lumavel/core/fixed.hpp"
#include "lumavel/core/limits.hpp"

namespace lumavel {

// One camera at the working resolution. Columns are meridians (the camera's
// y axis is vertical in the body frame), so a column has one body-frame yaw.
struct CameraGeometry {
  PixelQ16 fu;        // focal length, working pixels
  PixelQ16 cu;        // principal point column, working pixels (pixel 0 centre = 0)
  AngleQ28 axis_yaw;  // yaw of the optical axis in the body frame (CCW from body x)
  int8_t u_sign;      // d(body yaw)/du sign: -1 for an upright camera, +1 upside down
};

// A Gaussian-derivative kernel along the body yaw, repeated along the vertical.
struct KernelSpec {
  uint8_t order;   // derivative order 0..kMaxKernelOrder
  AngleQ28 sigma;  // scale, radians
};

struct EstimatorConfig {
  uint16_t width;   // working columns, kMinColumns..kMaxColumns
  uint16_t height;  // working rows, 1 (line scan)..kMaxRows
  CameraGeometry cam[2];
  LengthQ24 baseline;     // h: x of cam1's optical centre minus cam0's (signed)
  KernelSpec normaliser;  // order-0 window: the brightness that F is relative to
  KernelSpec kernels[kMaxKernels];
  uint8_t kernel_count;
  uint32_t tau_us;              // observer time constant
  uint32_t frame_period_us;     // nominal frame interval
  uint32_t max_gap_us;          // longest frame interval bridged; longer restarts
  uint32_t gyro_gap_us;         // gyro sample spacing that raises kStatusGyroGap
  ValueQ28 low_texture;         // rms of F1-F0 over kernels below which V is held
  uint16_t saturated_permille;  // clipped pixels (0 or 255) that raise kStatusSaturated
  uint8_t options;              // ConfigOption bits
  LengthQ24 still_distance;     // image change since a reference below this counts as still
  uint32_t still_min_us;        // stillness needed before the gyro offset is taken
  // Optional lens correction per camera: width + 1 values, each added to the
  // pinhole column edge (column_edge_yaws in kernel_bank.hpp). Lens distortion
  // is undistorted on the host and sent as this compact table (int16 instead
  // of a Q28 edge table: 2 x 129 x 2 bytes on a 128-column board), so the
  // firmware stays integer only. Read by configure() only, which builds the
  // kernel tables from it (neither it nor the edges are kept); nullptr =
  // pinhole from fu, cu.
  const EdgeOffsetQ15* edge_offsets[2];
  // Optional with a lens table: width values per camera, each column's
  // elevation scale (fixed.hpp), which sets the rows it sums and its tables'
  // weight (kernel_bank.hpp): a distorted column's rows do not see the
  // elevations a pinhole's would. Read by configure() only, like
  // edge_offsets; nullptr = the pinhole's cos(a_u) from the edges.
  const ElevationScaleQ14* elevation_scale[2];
};

enum ConfigOption : uint8_t {
  kOptionBaselineCorrection = 1u << 0,  // finite-baseline correction (x / tan x), see velocity_observer.hpp
  kOptionGyroOffsetLearning = 1u << 1,  // learn the gyro offset at standstill, see gyro_offset.hpp
  kOptionPhotometricBalance = 1u << 2,  // learn and correct cam1's response to cam0's, see photometric_balance.hpp
  kOptionElevationBand = 1u << 3,       // every column sums one elevation band (kernel_bank.hpp); default for wide views (config_fields.hpp)
  kOptionPhotometricMatch = 1u << 4,    // map cam1's black level and vignetting onto cam0's, see photometric_match.hpp
};
// (the photometric match only where it is built in: limits.hpp)
constexpr uint8_t kKnownOptions = kOptionBaselineCorrection | kOptionGyroOffsetLearning | kOptionPhotometricBalance |
                                  kOptionElevationBand | (kHavePhotometricMatch ? kOptionPhotometricMatch : 0);

enum class ConfigError : uint8_t {
  kOk = 0,
  kWidth,
  kHeight,
  kFocalLength,
  kPrincipalPoint,
  kAxisYaw,
  kUSign,
  kBaseline,
  kKernelCount,
  kKernelOrder,
  kKernelSigma,
  kKernelOutsideView,
  kTau,
  kFramePeriod,
  kMaxGap,
  kGyroGap,
  kLowTexture,
  kSaturatedPermille,
  kOptions,
  kStill,
  kColumnEdges,
};

// Names the first field that is out of range (kOk if none).
ConfigError validate(const EstimatorConfig& cfg);
const char* to_string(ConfigError e);

}  // namespace lumavel
