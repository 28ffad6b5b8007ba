// Host-side estimator settings in physical units (double). Both engines are
// built from these: the fixed engine after quantisation (to_fixed_config), the
// double reference engine directly, so the two see the same problem.
#pragma once
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "lumavel/core/config.hpp"
#include "lumavel/units/config_fields.hpp"

namespace lumavel::host {

struct CameraModel {
  double fu = 0, cu = 0;      // working-resolution pixels (pixel 0 centre = 0)
  double axis_yaw = 0;        // optical axis yaw in the body frame, rad (CCW from x)
  int u_sign = -1;            // d(body yaw)/du sign: -1 upright, +1 upside down
  // Optional column-edge yaws (width + 1, rad) overriding the pinhole model
  // (lens distortion); empty = pinhole.
  std::vector<double> edges;
  // Optional with edges: each column's elevation scale, f d(tan E)/d(row)
  // over the common band (lumavel/units/fixed.hpp ElevationScaleQ14, width
  // values); empty = the pinhole's cos of the column's yaw from the axis.
  std::vector<double> elevation_scale;
};

struct KernelModel {
  int order = 1;
  double sigma = 0.07;  // rad
};

// Defaults: the configuration authority (lumavel/units/config_fields.hpp),
// the device's too.
struct EstimatorSettings {
  using Q = config::Quantity;
  int width = kDefaultColumns, height = kDefaultRows;  // working resolution
  CameraModel cam[2];
  double baseline = config::spec(Q::kBaseline).def;   // m, x of cam1 minus x of cam0
  KernelModel normaliser{0, config::spec(Q::kKernelSigma).def};
  std::vector<KernelModel> kernels;
  double tau = config::spec(Q::kTau).def;                    // s
  double frame_period = config::spec(Q::kFramePeriod).def;   // s
  double max_gap = config::spec(Q::kMaxGap).def;             // s
  double gyro_gap = config::spec(Q::kGyroGap).def;           // s
  double low_texture = config::spec(Q::kLowTexture).def;     // rms of F1 - F0
  int saturated_permille = static_cast<int>(config::default_of<Q::kSaturatedPermille>);
  bool baseline_correction = true;  // finite-baseline correction (x / tan x per kernel)
  bool gyro_offset_learning = true;  // learn the gyro offset at standstill
  // Learn cam1's offset against cam0's (photometric_balance.hpp). Off by
  // default: on, the day soak's twin splits the time of flight on 88 frames
  // (it allows 52) and leaves the V allowance on 42 (docs/design.md).
  bool photometric_balance = false;
  // Map cam1's black level and vignetting onto cam0's, learned where one
  // camera stands where the other stood (photometric_match.hpp).
  bool photometric_match = true;
  // kOptionElevationBand: every column sums one elevation band (the default
  // from config::kElevationBandMinHfovRad on: derive_settings; docs/design.md,
  // "Column profile").
  bool elevation_band = false;
  double still_distance = config::spec(Q::kStillDistance).def;  // m: image change below this is standstill
  double still_min = config::spec(Q::kStillDuration).def;       // s of stillness before the offset is taken
};

// A setting the firmware configuration cannot take: what() names it, its
// value and the rule ("frame period = 2 s: frame period must be 1 ms..1 s");
// setting() is the EstimatorSettings member ("frame_period", "cam[1].fu",
// "baseline", "kernels", ...), for callers that know where it came from.
class SettingsError : public std::invalid_argument {
 public:
  SettingsError(std::string setting, const std::string& what)
      : std::invalid_argument(what), setting_(std::move(setting)) {}
  const std::string& setting() const { return setting_; }

 private:
  std::string setting_;
};

// Default kernel bank for a field of view (radians, horizontal):
// config::kDefaultKernels (the first kDefaultKernelsBuilt), the device's too
// (protocol::defaults_for).
std::vector<KernelModel> default_kernels(double hfov);

// The firmware configuration with the per-camera tables it points into
// (lens edge offsets, elevation scales; empty for a pinhole camera). Not
// copyable: `config` holds pointers into this object's vectors, so keep it
// where to_fixed_config() filled it while configure() reads it.
struct FixedConfig {
  EstimatorConfig config{};
  std::vector<EdgeOffsetQ15> edge_offsets[2];
  std::vector<ElevationScaleQ14> elevation_scale[2];
  FixedConfig() = default;
  FixedConfig(const FixedConfig&) = delete;
  FixedConfig& operator=(const FixedConfig&) = delete;
};

// Quantises to the firmware configuration, tables attached. Throws
// SettingsError naming the field, its value and the rule when a value does
// not fit its fixed-point format or is out of the core's range (validate()).
void to_fixed_config(const EstimatorSettings& s, FixedConfig& out);
// The same, checked with its tables but returned without them (edge_offsets
// and elevation_scale nullptr): for the scalar fields.
EstimatorConfig to_fixed_config(const EstimatorSettings& s);

// A gyro rate (rad/s) as the firmware takes it: RateQ24, rounded half away
// from zero, saturated at the rails (fx::rate_at_rail then says it was
// clipped). Not finite: throws std::invalid_argument.
RateQ24 to_fixed_rate(double rad_s);

// A camera's column-edge table in Q3.28 (empty for a pinhole camera).
std::vector<AngleQ28> to_fixed_edges(const CameraModel& c, int width);

// The same table as the firmware takes it: per-edge corrections (Q15 rad) to
// the pinhole edges of `fixed` (the quantised geometry, to_fixed_config's
// cam[i]). Empty for a pinhole camera; throws naming the edge whose
// correction does not fit [-1, 1) rad.
std::vector<EdgeOffsetQ15> to_fixed_edge_offsets(const CameraModel& c, const CameraGeometry& fixed, int width);

// The camera's elevation scales as the firmware takes them (Q1.14; empty for
// a pinhole camera); throws naming the column whose scale is outside (0, 2).
std::vector<ElevationScaleQ14> to_fixed_elevation_scale(const CameraModel& c, int width);

}  // namespace lumavel::host
