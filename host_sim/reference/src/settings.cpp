#include "lumavel/host/settings.hpp"

#include <cmath>
#include <cstdio>
#include <utility>
#include <stdexcept>
#include <string>

#include "lumavel/core/kernel_bank.hpp"
#include "lumavel/host/lens_table.hpp"
#include "lumavel/units/si.hpp"

namespace lumavel::host {
namespace {

// Values in messages: %g, 6 significant digits, never 300 digits.
std::string g(double v) {
  char b[64];
  std::snprintf(b, sizeof b, "%g", v);
  return b;
}

// Seconds as the configuration holds them, in whole microseconds (micros),
// which its rules are checked on: %g showed a frame period of 1.000000501 s,
// 1000001 us, as 'frame period = 1 s: frame period must be 1 ms..1 s', a
// refusal its own words allow. "1.000001", "0.016667", "0.000017" (%g
// for what is not a microsecond or more, and for what %f would print long).
// Under half a microsecond rounds to 0 us: %g too (was: frame timestamps in
// milliseconds, 17 ns apart, said 'frame period = 0 s: frame period must be
// 1 ms..1 s', a period the file does not have).
std::string us_text(double seconds) {
  const double us = std::round(seconds * 1e6);
  if (!(std::fabs(us) < 1e15) || (seconds != 0 && std::fabs(us) < 1)) return g(seconds);
  char b[64];
  std::snprintf(b, sizeof b, "%.6f", us / 1e6);
  std::string t = b;
  t.erase(t.find_last_not_of('0') + 1);
  if (t.back() == '.') t.pop_back();
  return t;
}

// `what` names the setting in messages ("focal length fu"), `setting` is
// its EstimatorSettings member, `unit` follows the value.
struct Field {
  const char* what;
  std::string setting;
  const char* unit;
};

int64_t quantise(double v, int frac, const Field& f, int64_t lo = INT32_MIN, int64_t hi = INT32_MAX) {
  if (!std::isfinite(v)) throw SettingsError(f.setting, std::string(f.what) + " = " + g(v) + ": not a finite number");
  const double q = std::round(std::ldexp(v, frac));
  if (q < static_cast<double>(lo) || q > static_cast<double>(hi))
  {
    const double top = std::ldexp(static_cast<double>(hi) + 1, -frac);
    const std::string range = lo == -hi - 1 ? "|value| < " + g(top) : g(std::ldexp(static_cast<double>(lo), -frac)) +
                                                                          " to " + g(top);
    const std::string unit = *f.unit ? std::string(" ") + f.unit : std::string();  // a ratio has none
    throw SettingsError(f.setting, std::string(f.what) + " = " + g(v) + unit + " does not fit its fixed-point format (" +
                                       range + unit + ")");
  }
  return static_cast<int64_t>(q);
}

uint32_t micros(double seconds, const Field& f) {
  return static_cast<uint32_t>(quantise(seconds * 1e6, 0, {f.what, f.setting, "us"}, 0, UINT32_MAX));
}

std::string cam_setting(int i, const char* member) { return "cam[" + std::to_string(i) + "]." + member; }

// The setting behind a validate() error, with its value: "frame period = 2 s".
std::pair<std::string, std::string> offending(const EstimatorSettings& s, ConfigError e) {
  auto worst_cam = [&](auto value) { return std::fabs(value(s.cam[1])) > std::fabs(value(s.cam[0])) ? 1 : 0; };
  switch (e) {
    case ConfigError::kWidth: return {"width", "working width = " + std::to_string(s.width)};
    case ConfigError::kHeight: return {"height", "working height = " + std::to_string(s.height)};
    case ConfigError::kFocalLength: {
      const config::FieldSpec& fu = config::spec(config::Quantity::kFocalLength);
      const int i = s.cam[0].fu < fu.lo || s.cam[0].fu > fu.hi ? 0 : 1;
      return {cam_setting(i, "fu"), "cam" + std::to_string(i) + " fu = " + g(s.cam[i].fu) + " px"};
    }
    case ConfigError::kPrincipalPoint: {
      const int i = s.cam[0].cu < -s.width || s.cam[0].cu > 2 * s.width ? 0 : 1;
      return {cam_setting(i, "cu"), "cam" + std::to_string(i) + " cu = " + g(s.cam[i].cu) + " px"};
    }
    case ConfigError::kAxisYaw: {
      const int i = worst_cam([](const CameraModel& c) { return c.axis_yaw; });
      return {cam_setting(i, "axis_yaw"), "cam" + std::to_string(i) + " axis yaw = " + g(s.cam[i].axis_yaw) + " rad"};
    }
    case ConfigError::kBaseline: return {"baseline", "baseline h = " + g(s.baseline) + " m"};
    case ConfigError::kTau: return {"tau", "observer tau = " + us_text(s.tau) + " s"};
    case ConfigError::kFramePeriod: return {"frame_period", "frame period = " + us_text(s.frame_period) + " s"};
    case ConfigError::kMaxGap: return {"max_gap", "max gap = " + us_text(s.max_gap) + " s"};
    case ConfigError::kGyroGap: return {"gyro_gap", "gyro gap = " + us_text(s.gyro_gap) + " s"};
    case ConfigError::kLowTexture: return {"low_texture", "low-texture threshold = " + g(s.low_texture)};
    case ConfigError::kStill:
      return {"still_distance", "still distance = " + g(s.still_distance) + " m, duration " + us_text(s.still_min) + " s"};
    case ConfigError::kColumnEdges: return {"cam[].edges", "a lens column-edge table"};
    case ConfigError::kKernelCount:
    case ConfigError::kKernelOrder:
    case ConfigError::kKernelSigma:
    case ConfigError::kKernelOutsideView: {
      std::string k = "kernels (order:sigma rad) =";
      for (const KernelModel& m : s.kernels) k += " " + std::to_string(m.order) + ":" + g(m.sigma);
      return {"kernels", k + ", normaliser sigma " + g(s.normaliser.sigma) + " rad"};
    }
    default: return {"", "the configuration"};
  }
}

}  // namespace

std::vector<KernelModel> default_kernels(double hfov) {
  const double half = hfov / 2;
  std::vector<KernelModel> out;
  for (int i = 0; i < config::kDefaultKernelsBuilt; ++i)
    out.push_back({config::kDefaultKernels[i].order, half / config::kDefaultKernels[i].half_view_divisor});
  return out;
}

void to_fixed_config(const EstimatorSettings& s, FixedConfig& out) {
  EstimatorConfig& c = out.config;
  c = EstimatorConfig{};
  if (s.width < kMinColumns || s.width > kMaxColumns)
    throw SettingsError("width", "working width " + std::to_string(s.width) + " is outside " +
                                     std::to_string(kMinColumns) + ".." + std::to_string(kMaxColumns));
  if (s.height < 1 || s.height > kMaxRows)
    throw SettingsError("height", "working height " + std::to_string(s.height) + " is outside 1.." + std::to_string(kMaxRows));
  c.width = static_cast<uint16_t>(s.width);
  c.height = static_cast<uint16_t>(s.height);
  for (int i = 0; i < 2; ++i) {
    c.cam[i].fu = static_cast<PixelQ16>(quantise(s.cam[i].fu, fx::kPixelFrac, {"focal length fu", cam_setting(i, "fu"), "px"}));
    c.cam[i].cu = static_cast<PixelQ16>(quantise(s.cam[i].cu, fx::kPixelFrac, {"principal point cu", cam_setting(i, "cu"), "px"}));
    c.cam[i].axis_yaw = static_cast<AngleQ28>(quantise(s.cam[i].axis_yaw, fx::kAngleFrac, {"axis yaw", cam_setting(i, "axis_yaw"), "rad"}));
    c.cam[i].u_sign = static_cast<int8_t>(s.cam[i].u_sign);
  }
  c.baseline = static_cast<LengthQ24>(quantise(s.baseline, fx::kLengthFrac, {"baseline h", "baseline", "m"}));
  c.normaliser.order = static_cast<uint8_t>(s.normaliser.order);
  c.normaliser.sigma = static_cast<AngleQ28>(quantise(s.normaliser.sigma, fx::kAngleFrac, {"normaliser sigma", "kernels", "rad"}));
  if (s.kernels.empty() || s.kernels.size() > static_cast<size_t>(kMaxKernels))
    throw SettingsError("kernels", "kernel count " + std::to_string(s.kernels.size()) + " is outside 1.." + std::to_string(kMaxKernels));
  c.kernel_count = static_cast<uint8_t>(s.kernels.size());
  for (size_t k = 0; k < s.kernels.size(); ++k) {
    if (s.kernels[k].order < 0 || s.kernels[k].order > kMaxKernelOrder)
      throw SettingsError("kernels", "kernel order " + std::to_string(s.kernels[k].order) + " is outside 0.." +
                                         std::to_string(kMaxKernelOrder));
    c.kernels[k].order = static_cast<uint8_t>(s.kernels[k].order);
    c.kernels[k].sigma = static_cast<AngleQ28>(quantise(s.kernels[k].sigma, fx::kAngleFrac, {"kernel sigma", "kernels", "rad"}));
  }
  c.tau_us = micros(s.tau, {"observer tau", "tau", "s"});
  c.frame_period_us = micros(s.frame_period, {"frame period", "frame_period", "s"});
  c.max_gap_us = micros(s.max_gap, {"max gap", "max_gap", "s"});
  c.gyro_gap_us = micros(s.gyro_gap, {"gyro gap", "gyro_gap", "s"});
  c.low_texture = static_cast<ValueQ28>(quantise(s.low_texture, fx::kValueFrac, {"low-texture threshold", "low_texture", ""}));
  if (s.saturated_permille < 0 || s.saturated_permille > 1000)
    throw SettingsError("saturated_permille", "saturated permille = " + std::to_string(s.saturated_permille) + " is outside 0..1000");
  c.saturated_permille = static_cast<uint16_t>(s.saturated_permille);
  c.options = static_cast<uint8_t>((s.baseline_correction ? kOptionBaselineCorrection : 0) |
                                   (s.gyro_offset_learning ? kOptionGyroOffsetLearning : 0) |
                                   (s.photometric_balance ? kOptionPhotometricBalance : 0) |
                                   (s.elevation_band ? kOptionElevationBand : 0) |
                                   (s.photometric_match ? kOptionPhotometricMatch : 0));
  c.still_distance = static_cast<LengthQ24>(quantise(s.still_distance, fx::kLengthFrac, {"still distance", "still_distance", "m"}));
  c.still_min_us = micros(s.still_min, {"still duration", "still_min", "s"});
  for (int i = 0; i < 2; ++i) {
    out.edge_offsets[i] = to_fixed_edge_offsets(s.cam[i], c.cam[i], s.width);
    c.edge_offsets[i] = out.edge_offsets[i].empty() ? nullptr : out.edge_offsets[i].data();
    out.elevation_scale[i] = to_fixed_elevation_scale(s.cam[i], s.width);
    c.elevation_scale[i] = out.elevation_scale[i].empty() ? nullptr : out.elevation_scale[i].data();
  }
  const ConfigError e = validate(c);
  if (e != ConfigError::kOk) {
    const auto [setting, value] = offending(s, e);
    throw SettingsError(setting, value + ": " + to_string(e));
  }
}

EstimatorConfig to_fixed_config(const EstimatorSettings& s) {
  FixedConfig f;
  to_fixed_config(s, f);
  EstimatorConfig c = f.config;
  c.edge_offsets[0] = c.edge_offsets[1] = nullptr;  // the vectors die with f
  c.elevation_scale[0] = c.elevation_scale[1] = nullptr;
  return c;
}

RateQ24 to_fixed_rate(double rad_s) {
  if (!std::isfinite(rad_s)) throw std::invalid_argument("gyro rate is not a finite number");
  return si::Rate::from_si(rad_s);
}

std::vector<AngleQ28> to_fixed_edges(const CameraModel& c, int width) {
  std::vector<AngleQ28> out;
  if (c.edges.empty()) return out;
  if (c.edges.size() != static_cast<size_t>(width) + 1)
    throw SettingsError("cam[].edges", "column-edge table has " + std::to_string(c.edges.size()) + " values for " +
                                std::to_string(width) + " columns (want width + 1)");
  for (double e : c.edges) out.push_back(static_cast<AngleQ28>(quantise(e, fx::kAngleFrac, {"column edge", "cam[].edges", "rad"})));
  return out;
}

std::vector<EdgeOffsetQ15> to_fixed_edge_offsets(const CameraModel& c, const CameraGeometry& fixed, int width) {
  const std::vector<AngleQ28> exact = to_fixed_edges(c, width);
  if (exact.empty()) return {};
  LensTable t = lens_table(fixed, static_cast<uint16_t>(width), exact);
  if (t.bad_edge >= 0) {  // quantise() names the edge and the Q15 range: it throws here
    const std::string field = "lens correction of column edge " + std::to_string(t.bad_edge);
    quantise(t.bad_offset_rad, fx::kEdgeOffsetFrac, {field.c_str(), "cam[].edges", "rad"}, INT16_MIN, INT16_MAX);
  }
  return std::move(t.offsets);
}

std::vector<ElevationScaleQ14> to_fixed_elevation_scale(const CameraModel& c, int width) {
  std::vector<ElevationScaleQ14> out;
  if (c.elevation_scale.empty()) return out;
  if (c.elevation_scale.size() != static_cast<size_t>(width))
    throw SettingsError("cam[].elevation_scale", "elevation-scale table has " + std::to_string(c.elevation_scale.size()) +
                                                     " values for " + std::to_string(width) + " columns (want width)");
  for (size_t u = 0; u < c.elevation_scale.size(); ++u) {
    const std::string field = "elevation scale of column " + std::to_string(u);
    out.push_back(static_cast<ElevationScaleQ14>(quantise(c.elevation_scale[u], fx::kElevationScaleFrac,
                                                          {field.c_str(), "cam[].elevation_scale", ""}, 1,
                                                          (2 << fx::kElevationScaleFrac) - 1)));
  }
  return out;
}

}  // namespace lumavel::host
