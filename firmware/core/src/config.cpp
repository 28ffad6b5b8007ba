#include "lumavel/core/config.hpp"

#include "lumavel/core/imath.hpp"
#include "lumavel/core/kernel_bank.hpp"
#include "lumavel/units/config_fields.hpp"

namespace lumavel {
namespace {

// The ranges: lumavel/units/config_fields.hpp (shared with the wire codec).
using config::Quantity;
using config::range;

bool kernel_ok(const KernelSpec& k, bool order_zero_only) {
  if (order_zero_only ? k.order != 0 : k.order > kMaxKernelOrder) return false;
  return true;
}

// A camera's column edges (pinhole plus the lens table, if any) must lie in
// [-pi, pi] and run strictly monotonically in the camera's u direction.
bool edges_ok(const AngleQ28* e, uint16_t width, int8_t u_sign) {
  for (uint16_t u = 0; u <= width; ++u)
    if (e[u] < -fx::kPiQ28 || e[u] > fx::kPiQ28) return false;
  for (uint16_t u = 0; u < width; ++u)
    if (u_sign > 0 ? e[u + 1] <= e[u] : e[u + 1] >= e[u]) return false;
  return true;
}

}  // namespace

ConfigError validate(const EstimatorConfig& c) {
  if (c.width < kMinColumns || c.width > kMaxColumns) return ConfigError::kWidth;
  if (c.height < 1 || c.height > kMaxRows) return ConfigError::kHeight;
  for (const CameraGeometry& g : c.cam) {
    if (!range<Quantity::kFocalLength>.holds(g.fu)) return ConfigError::kFocalLength;
    const int64_t w = int64_t{c.width} << 16;
    if (g.cu < -w || g.cu > 2 * w) return ConfigError::kPrincipalPoint;
    if (g.axis_yaw < -fx::kPiQ28 || g.axis_yaw > fx::kPiQ28) return ConfigError::kAxisYaw;
    if (g.u_sign != 1 && g.u_sign != -1) return ConfigError::kUSign;
  }
  // Either sign.
  const int64_t h = c.baseline < 0 ? -int64_t{c.baseline} : c.baseline;
  if (!range<Quantity::kBaseline>.holds(h)) return ConfigError::kBaseline;
  if (c.kernel_count < 1 || c.kernel_count > kMaxKernels) return ConfigError::kKernelCount;
  if (!kernel_ok(c.normaliser, true)) return ConfigError::kKernelOrder;
  for (int k = 0; k < c.kernel_count; ++k)
    if (!kernel_ok(c.kernels[k], false)) return ConfigError::kKernelOrder;
  const KernelSpec* all[kMaxKernels + 1];
  int n = 0;
  all[n++] = &c.normaliser;
  for (int k = 0; k < c.kernel_count; ++k) all[n++] = &c.kernels[k];
  for (int i = 0; i < n; ++i)
    if (!range<Quantity::kKernelSigma>.holds(all[i]->sigma)) return ConfigError::kKernelSigma;
  // Each kernel's +-2.5 sigma core must lie inside both views (the side
  // strips of paper eq. 19 take the tails).
  const int64_t centre = (int64_t{c.cam[0].axis_yaw} + c.cam[1].axis_yaw) / 2;
  for (int cam = 0; cam < 2; ++cam) {
    AngleQ28 edges[kMaxColumns + 1];
    column_edge_yaws(c.cam[cam], c.edge_offsets[cam], c.width, edges);
    if (c.edge_offsets[cam] && !edges_ok(edges, c.width, c.cam[cam].u_sign)) return ConfigError::kColumnEdges;
    if (c.elevation_scale[cam])
      for (uint16_t u = 0; u < c.width; ++u)
        if (c.elevation_scale[cam][u] == 0 || c.elevation_scale[cam][u] >= 2u << fx::kElevationScaleFrac)
          return ConfigError::kColumnEdges;
    const int64_t lo = edges[0] < edges[c.width] ? edges[0] : edges[c.width];
    const int64_t hi = edges[0] < edges[c.width] ? edges[c.width] : edges[0];
    for (int i = 1; i < n; ++i) {
      const int64_t reach = all[i]->sigma * 5 / 2;
      if (centre - reach < lo || centre + reach > hi) return ConfigError::kKernelOutsideView;
    }
  }
  if (!range<Quantity::kTau>.holds(c.tau_us)) return ConfigError::kTau;
  if (!range<Quantity::kFramePeriod>.holds(c.frame_period_us)) return ConfigError::kFramePeriod;
  if (c.max_gap_us < c.frame_period_us || !range<Quantity::kMaxGap>.holds(c.max_gap_us)) return ConfigError::kMaxGap;
  if (!range<Quantity::kGyroGap>.holds(c.gyro_gap_us)) return ConfigError::kGyroGap;
  if (!range<Quantity::kLowTexture>.holds(c.low_texture)) return ConfigError::kLowTexture;
  if (!range<Quantity::kSaturatedPermille>.holds(c.saturated_permille)) return ConfigError::kSaturatedPermille;
  if ((c.options & ~kKnownOptions) != 0) return ConfigError::kOptions;
  if (!range<Quantity::kStillDistance>.holds(c.still_distance) || !range<Quantity::kStillDuration>.holds(c.still_min_us))
    return ConfigError::kStill;
  return ConfigError::kOk;
}

const char* to_string(ConfigError e) {
  switch (e) {
    case ConfigError::kOk: return "ok";
    case ConfigError::kWidth: return "width must be 16..LUMAVEL_MAX_COLS columns";
    case ConfigError::kHeight: return "height must be 1..LUMAVEL_MAX_ROWS rows";
    case ConfigError::kFocalLength: return "focal length fu must be 1..30000 px";
    case ConfigError::kPrincipalPoint: return "principal point cu must lie in [-width, 2 width]";
    case ConfigError::kAxisYaw: return "optical axis yaw must be in [-pi, pi]";
    case ConfigError::kUSign: return "u_sign must be +1 or -1";
    case ConfigError::kBaseline: return "baseline |h| must be 1 mm..1 m";
    case ConfigError::kKernelCount: return "kernel count must be 1..LUMAVEL_MAX_KERNELS";
    case ConfigError::kKernelOrder: return "kernel order must be 0..3 (normaliser: 0)";
    case ConfigError::kKernelSigma: return "kernel sigma must be 0.5..45 deg";
    case ConfigError::kKernelOutsideView: return "a kernel's +-2.5 sigma core falls outside a camera's view";
    case ConfigError::kTau: return "observer time constant must be 1 ms..10 s";
    case ConfigError::kFramePeriod: return "frame period must be 1 ms..1 s";
    case ConfigError::kMaxGap: return "max gap must be one frame period..4 s";
    case ConfigError::kGyroGap: return "gyro gap must be 0.1 ms..1 s";
    case ConfigError::kLowTexture: return "low-texture threshold must be 0..1";
    case ConfigError::kSaturatedPermille: return "saturated permille must be 0..1000";
    case ConfigError::kOptions: return "unknown option bits";
    case ConfigError::kColumnEdges: return "lens table: column edges must be monotonic in u and within [-pi, pi], elevation scales in (0, 2)";
    case ConfigError::kStill: return "stillness distance must be 0.1 mm..10 cm and its duration 0.1..60 s";
  }
  return "unknown configuration error";
}

}  // namespace lumavel
