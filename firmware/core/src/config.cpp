#include "lumavel/core/config.hpp"

#include "lumavel/core/imath.hpp"
#include "lumavel/core/kernel_bank.hpp"

namespace lumavel {
namespace {

constexpr int64_t kDegQ28 = 4685082;  // 1 degree in Q3.28 rad
constexpr int64_t kMinSigma = kDegQ28 / 2;
constexpr int64_t kMaxSigma = 45 * kDegQ28;

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
    // 1 px .. 30000 px focal length (working resolution).
    if (g.fu < (int32_t{1} << 16) || int64_t{g.fu} > int64_t{30000} << 16) return ConfigError::kFocalLength;
    const int64_t w = int64_t{c.width} << 16;
    if (g.cu < -w || g.cu > 2 * w) return ConfigError::kPrincipalPoint;
    if (g.axis_yaw < -fx::kPiQ28 || g.axis_yaw > fx::kPiQ28) return ConfigError::kAxisYaw;
    if (g.u_sign != 1 && g.u_sign != -1) return ConfigError::kUSign;
  }
  // 1 mm .. 2 m, either sign.
  const int64_t h = c.baseline < 0 ? -int64_t{c.baseline} : c.baseline;
  if (h < (int64_t{1} << 24) / 1000 || h > (int64_t{2} << 24)) return ConfigError::kBaseline;
  if (c.kernel_count < 1 || c.kernel_count > kMaxKernels) return ConfigError::kKernelCount;
  if (!kernel_ok(c.normaliser, true)) return ConfigError::kKernelOrder;
  for (int k = 0; k < c.kernel_count; ++k)
    if (!kernel_ok(c.kernels[k], false)) return ConfigError::kKernelOrder;
  const KernelSpec* all[kMaxKernels + 1];
  int n = 0;
  all[n++] = &c.normaliser;
  for (int k = 0; k < c.kernel_count; ++k) all[n++] = &c.kernels[k];
  for (int i = 0; i < n; ++i)
    if (all[i]->sigma < kMinSigma || all[i]->sigma > kMaxSigma) return ConfigError::kKernelSigma;
  // Each kernel's +-2.5 sigma core must lie inside both views (the side
  // strips of paper eq. 19 take the tails).
  const int64_t centre = (int64_t{c.cam[0].axis_yaw} + c.cam[1].axis_yaw) / 2;
  for (int cam = 0; cam < 2; ++cam) {
    AngleQ28 edges[kMaxColumns + 1];
    column_edge_yaws(c.cam[cam], c.edge_offsets[cam], c.width, edges);
    if (c.edge_offsets[cam] && !edges_ok(edges, c.width, c.cam[cam].u_sign)) return ConfigError::kColumnEdges;
    const int64_t lo = edges[0] < edges[c.width] ? edges[0] : edges[c.width];
    const int64_t hi = edges[0] < edges[c.width] ? edges[c.width] : edges[0];
    for (int i = 1; i < n; ++i) {
      const int64_t reach = all[i]->sigma * 5 / 2;
      if (centre - reach < lo || centre + reach > hi) return ConfigError::kKernelOutsideView;
    }
  }
  if (c.tau_us < 1000 || c.tau_us > 10000000) return ConfigError::kTau;
  if (c.frame_period_us < 100 || c.frame_period_us > 1000000) return ConfigError::kFramePeriod;
  if (c.max_gap_us < c.frame_period_us || c.max_gap_us > 4000000) return ConfigError::kMaxGap;
  if (c.gyro_gap_us < 100 || c.gyro_gap_us > 4000000) return ConfigError::kGyroGap;
  if (c.low_texture < 0 || c.low_texture > (int32_t{1} << 28)) return ConfigError::kLowTexture;
  if (c.saturated_permille > 1000) return ConfigError::kSaturatedPermille;
  if ((c.options & ~kKnownOptions) != 0) return ConfigError::kOptions;
  // 0.1 mm .. 10 cm; 0.1 s .. 60 s.
  if (c.still_distance < 1678 || c.still_distance > 1677722 || c.still_min_us < 100000 || c.still_min_us > 60000000)
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
    case ConfigError::kBaseline: return "baseline |h| must be 1 mm..2 m";
    case ConfigError::kKernelCount: return "kernel count must be 1..LUMAVEL_MAX_KERNELS";
    case ConfigError::kKernelOrder: return "kernel order must be 0..3 (normaliser: 0)";
    case ConfigError::kKernelSigma: return "kernel sigma must be 0.5..45 deg";
    case ConfigError::kKernelOutsideView: return "a kernel's +-2.5 sigma core falls outside a camera's view";
    case ConfigError::kTau: return "observer time constant must be 1 ms..10 s";
    case ConfigError::kFramePeriod: return "frame period must be 0.1 ms..1 s";
    case ConfigError::kMaxGap: return "max gap must be one frame period..4 s";
    case ConfigError::kGyroGap: return "gyro gap must be 0.1 ms..4 s";
    case ConfigError::kLowTexture: return "low-texture threshold must be 0..1";
    case ConfigError::kSaturatedPermille: return "saturated permille must be 0..1000";
    case ConfigError::kOptions: return "unknown option bits";
    case ConfigError::kColumnEdges: return "lens table: column edges must be monotonic in u and within [-pi, pi]";
    case ConfigError::kStill: return "stillness distance must be 0.1 mm..10 cm and its duration 0.1..60 s";
  }
  return "unknown configuration error";
}

}  // namespace lumavel
