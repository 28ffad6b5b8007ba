// The configuration authority: every ranged configuration quantity once, with
// its range and default in SI units. The core's validate()
// (core/config.hpp), the wire codec's validate() (protocol/device_config.hpp)
// and the host's conversion (host_sim/reference settings.hpp) all read this
// table, so that a value the wire accepts is one the core accepts.
//
// Firmware stays integer only: the doubles here are only ever folded into
// integers at compile time (range<Q> and default_of<Q> are constexpr
// variables), as fusion_params.hpp does. Host code may read kFields at run
// time (names, SI values for messages).
//
// Where the core and the wire used to disagree, the tighter range won (the
// core's physical limit for tau, max gap and kernel sigma, the wire's for the
// baseline, frame period and gyro gap): one range for both, the intersection.
#pragma once
#include <cstdint>

#include "lumavel/units/limits.hpp"

namespace lumavel::config {

enum class Quantity : uint8_t {
  kBaseline,
  kMisalignment,
  kFocalLength,
  kKernelSigma,
  kTau,
  kFramePeriod,
  kMaxGap,
  kGyroGap,
  kLowTexture,
  kSaturatedPermille,
  kStillDistance,
  kStillDuration,
  kCount,
};

struct FieldSpec {
  Quantity id;
  const char* name;  // as the host settings call it
  const char* unit;  // of lo, hi, def
  double lo, hi;     // SI range, inclusive (the baseline: of |h|)
  double def;        // the default
  double per_unit;   // integer counts per SI unit: 2^frac for a Q format, 1e6 for us
};

constexpr double kQ16 = 65536.0, kQ24 = 16777216.0, kQ28 = 268435456.0;
constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180;

// One row per Quantity, in its order (checked below). Why each range is what it is:
constexpr FieldSpec kFields[] = {
    // h = x(cam1) - x(cam0), either sign. Below 1 mm the two views'
    // difference drowns in pixel noise; beyond 1 m the cameras no longer see
    // the same near scene (and a rig that long is not this sensor's job).
    {Quantity::kBaseline, "baseline", "m", 0.001, 1.0, 0.08, kQ24},
    // Yaw from cam0 to cam1 (wire only): 20 degrees is a gross mounting
    // error already; beyond it the kernels' cores leave the second view.
    {Quantity::kMisalignment, "misalignment", "rad", -0.35, 0.35, 0.0, kQ28},
    // Working pixels: the Q15.16 format ends at 32768 px; 30000 leaves room.
    // (The wire also holds fu to 8 x width, a field of view >= 7 degrees.)
    {Quantity::kFocalLength, "fu", "px", 1.0, 30000.0, 0.0 /* none: defaults_for */, kQ16},
    // Kernel and normaliser scale: below half a degree a kernel covers about
    // one column even at 160 columns over 60 degrees; at 45 degrees its
    // +-2.5 sigma core already spans more than a half turn. The default is
    // the normaliser's.
    {Quantity::kKernelSigma, "sigma", "rad", 0.5 * kDeg, 45 * kDeg, 0.20, kQ28},
    // Observer time constant: from a frame or so up to 10 s (the core's
    // limit, which the wire's 60 s used to exceed); a slower observer does
    // not follow a vehicle.
    {Quantity::kTau, "tau", "s", 0.001, 10.0, 0.1, 1e6},
    // Nominal frame interval: 1 kHz to 1 Hz, the cameras this is made for
    // (the app counts gaps with a period in ns in 32 bits).
    {Quantity::kFramePeriod, "frame_period", "s", 0.001, 1.0, 1.0 / 60, 1e6},
    // Longest frame interval bridged (and at least one frame period): past
    // 4 s the observer's state says nothing about the motion any more, and
    // 4 s is the longest gyro interval integrated in one piece
    // (gyro_integrator.cpp: |rate sum| * dt stays inside 64 bits).
    {Quantity::kMaxGap, "max_gap", "s", 0.0, 4.0, 0.5, 1e6},
    // Gyro sample spacing that raises the gyro-gap status: up to 1 s; a gyro
    // slower than that cannot follow a turn.
    {Quantity::kGyroGap, "gyro_gap", "s", 0.0001, 1.0, 0.05, 1e6},
    // rms of F1 - F0 over the kernels (normalised, so 0..1).
    {Quantity::kLowTexture, "low_texture", "", 0.0, 1.0, 2e-3, kQ28},
    // Clipped pixels, per mille of a frame.
    {Quantity::kSaturatedPermille, "saturated_permille", "permille", 0.0, 1000.0, 50.0, 1.0},
    // Image change below which the rig counts as still (gyro_offset.hpp):
    // 0.1 mm is below any noise floor, 10 cm is plain motion.
    {Quantity::kStillDistance, "still_distance", "m", 0.0001, 0.1, 0.002, kQ24},
    // Stillness before the gyro offset is taken: a few frames to a minute.
    {Quantity::kStillDuration, "still_min", "s", 0.1, 60.0, 0.5, 1e6},
};
constexpr int kFieldCount = static_cast<int>(Quantity::kCount);
static_assert(sizeof kFields / sizeof kFields[0] == kFieldCount, "one row per Quantity");

constexpr bool rows_in_order() {
  for (int i = 0; i < kFieldCount; ++i)
    if (static_cast<int>(kFields[i].id) != i) return false;
  return true;
}
static_assert(rows_in_order(), "kFields rows follow Quantity's order");

constexpr const FieldSpec& spec(Quantity q) { return kFields[static_cast<int>(q)]; }

// An SI value in integer counts, rounded half away from zero.
constexpr int64_t to_counts(double si, double per_unit) {
  const double x = si * per_unit;
  return x < 0 ? -static_cast<int64_t>(-x + 0.5) : static_cast<int64_t>(x + 0.5);
}

struct Range {
  int64_t lo, hi;
  constexpr bool holds(int64_t v) const { return v >= lo && v <= hi; }
};

// Compile-time integer forms (variables, so the doubles never reach run time).
template <Quantity Q>
inline constexpr Range range = {to_counts(spec(Q).lo, spec(Q).per_unit), to_counts(spec(Q).hi, spec(Q).per_unit)};
template <Quantity Q>
inline constexpr int64_t default_of = to_counts(spec(Q).def, spec(Q).per_unit);

// Every default inside its range (fu has none: it follows the resolution, defaults_for).
constexpr bool defaults_in_range() {
  for (const FieldSpec& f : kFields)
    if (f.id != Quantity::kFocalLength && (f.def < f.lo || f.def > f.hi)) return false;
  return true;
}
static_assert(defaults_in_range(), "a default outside its own range");
static_assert(range<Quantity::kMaxGap>.hi >= range<Quantity::kFramePeriod>.hi, "max gap >= one frame period");
static_assert(int64_t{8} * kMaxColumns <= 30000, "the wire's fu <= 8 x width stays inside the core's fu range");
// The wire's optical axes are +-pi/2 plus the misalignment: inside the core's [-pi, pi].
static_assert(to_counts(kPi / 2, kQ28) + range<Quantity::kMisalignment>.hi <= to_counts(kPi, kQ28), "axis yaw");

// ---- default geometry ----

// A horizontal field of view as the defaults use it: the focal length at the
// default working width (kDefaultColumns), Q16 px. Other widths scale it
// (defaults_for in protocol/device_config.hpp). Firmware: constexpr only.
constexpr double tan_of(double x) {  // |x| < pi/2; Taylor series of sin and cos
  double s = 0, c = 0, term = 1;
  for (int n = 0; n < 30; ++n) {
    if (n > 0) term *= x / n;
    if (n % 4 == 0) c += term;
    if (n % 4 == 1) s += term;
    if (n % 4 == 2) c -= term;
    if (n % 4 == 3) s -= term;
  }
  return s / c;
}
// ---- the default kernel bank ----
// One bank for the device and the host, sized to the view: each kernel is
// below 1 % of its peak on the outer ~12 % of each side of the view (the side
// strips of paper eq. 19, with room for a couple of degrees of misalignment):
// sigma = half view / 4 and / 6, orders 1 and 2. Two first-order kernels alone
// (what the device ran until 2026-12) cost half the kernel phase but read every
// study of docs/results.md worse, most of all the paper's simulated rig (worst
// error after 1 s 0.005 -> 0.35 m/s at 160x120) and near clutter (3.4 -> 7.4 %):
// docs/design.md, "Kernel bank".
struct DefaultKernel {
  int order;
  double half_view_divisor;  // sigma = (hfov / 2) / this
};
constexpr DefaultKernel kDefaultKernels[] = {{1, 4.0}, {2, 4.0}, {1, 6.0}, {2, 6.0}};
constexpr int kDefaultKernelCount = 4;
static_assert(sizeof kDefaultKernels / sizeof kDefaultKernels[0] == kDefaultKernelCount, "count");
// A build with fewer kernel slots (LUMAVEL_MAX_KERNELS, e.g. the 8 KiB part's
// 3) takes the first ones of the default set.
constexpr int kDefaultKernelsBuilt = kDefaultKernelCount < kMaxKernels ? kDefaultKernelCount : kMaxKernels;

// The elevation band (kOptionElevationBand: every column sums the rows all
// columns see) is the default from this horizontal field of view on. Under a
// turn the scene slides through each column's elevation reach, which narrows
// as cos(yaw); the default edge-row correction undoes it to first order and
// the band exactly, for fewer rows. Measured on the slalom (+-1 rad/s, photo
// wall at 1.5 m) rendered at hfov 50 / 60 / 70 / 80 / 100 / 120, 40x30 (E,
// correction -> band): 3.68 -> 3.60, 2.49 -> 2.59, 1.96 -> 2.12, 4.06 -> 2.38,
// 2.05 -> 1.47, 3.62 -> 2.31 %; the spin in place at hfov 90, worst spurious
// V 0.036 -> 0.018 m/s. What it costs on straight passes at hfov 90: a photo
// wall 0.93 -> 1.15 %, back and forth among clutter 23.4 -> 26.0 %
// (docs/design.md, "Column profile").
constexpr double kElevationBandMinHfovRad = 80 * kDeg;
constexpr bool elevation_band_for(double hfov_rad) { return hfov_rad >= kElevationBandMinHfovRad; }

// A horizontal field of view as the defaults use it: the focal length at the
// default working width (kDefaultColumns), Q16 px, and the default kernels'
// sigmas for it, Q28 rad, and whether it bands by default. Other widths scale
// the focal length (defaults_for in protocol/device_config.hpp); the kernels
// keep their angles. Firmware: constexpr only.
struct FieldOfView {
  int32_t fu_at_default_width;                // PixelQ16
  int32_t kernel_sigma[kDefaultKernelCount];  // AngleQ28, kDefaultKernels sized to this view
  bool elevation_band;                        // elevation_band_for(this view)
};
constexpr FieldOfView field_of_view(double hfov_rad) {
  FieldOfView f{static_cast<int32_t>(to_counts(0.5 * kDefaultColumns / tan_of(hfov_rad / 2), kQ16)), {},
                elevation_band_for(hfov_rad)};
  for (int k = 0; k < kDefaultKernelCount; ++k)
    f.kernel_sigma[k] = static_cast<int32_t>(to_counts(hfov_rad / 2 / kDefaultKernels[k].half_view_divisor, kQ28));
  return f;
}
constexpr double kDefaultFovRad = 60 * kDeg;
inline constexpr FieldOfView kDefaultFov = field_of_view(kDefaultFovRad);
static_assert(kDefaultFov.fu_at_default_width == 2270234, "34.64 px: 60 degrees over 40 columns");

}  // namespace lumavel::config
