// One interface over both estimator engines, so every host tool can select
// the fixed-point firmware core or the double-precision reference; the same
// interface carries the keypoint stereo VO baseline (host_sim/vo), which is
// built from a recording rather than from EstimatorSettings.
#pragma once
#include <cstdint>
#include <memory>
#include <string>

#include "lumavel/host/settings.hpp"

namespace lumavel::host {

struct EngineEstimate {
  uint64_t t_ns = 0;
  double v = 0;         // m/s
  double distance = 0;  // m
  double heading = 0;   // rad, wrapped to [-pi, pi)
  uint16_t status = 0;  // lumavel::StatusFlag bits
  double v_direct = 0;  // this interval's direct measurement, m/s
  double texture = 0;   // rms of F1 - F0 over kernels
  double gyro_offset = 0;  // learned zero-rate offset, rad/s
  double v_differential = 0;  // the differential observer alone, m/s (v fuses it with the time of flight)
  double tof_s = 0;           // this frame's time of flight, s (0: none)
  double scale = 1;           // the differential's learned scale against the time of flight
  bool outvoted = false;      // the differential outvoted by the time of flight (Estimate::outvoted)
  // The photometric match's mapping in use (photometric_match.hpp): cam1's
  // column gain tilt a1 and vignetting a2, and its black level over cam0's, DN.
  double photometric[3] = {0, 0, 0};
};

enum class EngineKind { kFixed, kFloat, kVo };
EngineKind parse_engine_kind(const std::string& name);  // "fixed" | "float" | "vo"; throws
const char* engine_name(EngineKind k);

class Engine {
 public:
  virtual ~Engine() = default;
  virtual void push_gyro(uint64_t t_ns, double rate_z) = 0;  // rad/s
  // Frames at the working resolution, width * height bytes each.
  virtual EngineEstimate step(uint64_t t_ns, const uint8_t* cam0, const uint8_t* cam1) = 0;
};

// Throws std::invalid_argument when the settings are out of range, and for
// kVo (make it with make_vo_engine from the recording: it needs the camera
// models, which the settings do not carry).
std::unique_ptr<Engine> make_engine(EngineKind kind, const EstimatorSettings& s);

}  // namespace lumavel::host
