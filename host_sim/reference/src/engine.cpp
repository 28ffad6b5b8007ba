#include "lumavel/host/engine.hpp"

#include <cmath>
#include <stdexcept>

#include "lumavel/core/estimator.hpp"
#include "lumavel/core/photometric_params.hpp"
#include "lumavel/host/float_estimator.hpp"
#include "lumavel/units/si.hpp"

namespace lumavel::host {
namespace {

class FixedEngine final : public Engine {
 public:
  explicit FixedEngine(const EstimatorSettings& s) : est_(std::make_unique<Estimator>()) {
    FixedConfig c;
    to_fixed_config(s, c);
    const ConfigError e = est_->configure(c.config);
    if (e != ConfigError::kOk) throw std::invalid_argument(to_string(e));
    width_ = s.width;
  }
  void push_gyro(uint64_t t_ns, double rate_z) override { est_->push_gyro(t_ns, to_fixed_rate(rate_z)); }
  EngineEstimate step(uint64_t t_ns, const uint8_t* cam0, const uint8_t* cam1) override {
    FramePair f{t_ns, {cam0, cam1}, static_cast<uint16_t>(width_)};
    const Estimate e = est_->step(f);
    EngineEstimate o;
    o.t_ns = e.t_ns;
    o.v = si::Speed::to_si(e.v);
    o.distance = si::Distance::to_si(e.distance);
    o.heading = si::Angle::to_si(e.heading);
    o.status = e.status;
    o.v_direct = si::Speed::to_si(e.v_direct);
    o.texture = si::Value::to_si(e.texture);
    o.gyro_offset = si::Rate::to_si(e.gyro_offset);
    o.v_differential = si::Speed::to_si(e.v_differential);
    o.tof_s = static_cast<double>(e.tof_ns) * 1e-9;
    o.scale = si::Scale::to_si(e.scale);
    o.outvoted = e.outvoted;
    int32_t p[kMatchParams];
    est_->photometric_params(p);
    for (int j = 0; j < kMatchParams; ++j) o.photometric[j] = static_cast<double>(p[j]) / 1073741824.0;
    o.photometric[2] *= params::kMatchOffsetUnitDn;
    return o;
  }

 private:
  std::unique_ptr<Estimator> est_;
  int width_ = 0;
};

class FloatEngine final : public Engine {
 public:
  explicit FloatEngine(const EstimatorSettings& s) : est_(s) {}
  void push_gyro(uint64_t t_ns, double rate_z) override { est_.push_gyro(t_ns, rate_z); }
  EngineEstimate step(uint64_t t_ns, const uint8_t* cam0, const uint8_t* cam1) override {
    return est_.step(t_ns, cam0, cam1);
  }

 private:
  FloatEstimator est_;
};

}  // namespace

EngineKind parse_engine_kind(const std::string& name) {
  if (name == "fixed") return EngineKind::kFixed;
  if (name == "float") return EngineKind::kFloat;
  if (name == "vo") return EngineKind::kVo;
  throw std::invalid_argument("unknown engine '" + name + "' (expected fixed, float or vo)");
}

const char* engine_name(EngineKind k) {
  switch (k) {
    case EngineKind::kFixed: return "fixed";
    case EngineKind::kFloat: return "float";
    case EngineKind::kVo: return "vo";
  }
  return "?";
}

std::unique_ptr<Engine> make_engine(EngineKind kind, const EstimatorSettings& s) {
  if (kind == EngineKind::kFixed) return std::make_unique<FixedEngine>(s);
  if (kind == EngineKind::kVo)
    throw std::invalid_argument("the vo engine is built from a recording's camera models (make_vo_engine)");
  return std::make_unique<FloatEngine>(s);
}

}  // namespace lumavel::host
