// The device configuration (protocol::DeviceConfig, the wire's form) as the
// estimator's EstimatorConfig. The bridge between the codec and the core:
// it lives in the app so that the codec does not depend on the core's
// configuration. Host tools that mirror a device use it too. Integer only.
#pragma once
#include "lumavel/core/config.hpp"
#include "lumavel/protocol/device_config.hpp"

namespace lumavel::app {

// Builds the estimator's configuration. False (out untouched) if
// protocol::validate() refuses c, or c.lens names a camera whose entry in
// `lens` is null. The estimator's edge_offsets point into `lens` (read by
// configure() only). The estimator still runs its own validate() in configure().
bool to_estimator_config(const protocol::DeviceConfig& c, EstimatorConfig& out,
                         const EdgeOffsetQ15* const lens[2] = nullptr);

}  // namespace lumavel::app
