// Runs the firmware app over a recorded stream: the whole "board" of the
// QEMU firmware and of the host build, so both run exactly this code and only
// their byte source/sink differ.
#pragma once
#include <cstdint>

#include "lumavel/app/app.hpp"
#include "lumavel/protocol/device_config.hpp"
#include "lumavel/stream/byte_io.hpp"
#include "lumavel/stream/stream_hal.hpp"

namespace lumavel::stream {

enum class RunOutcome : uint8_t { kOk = 0, kBadStream = 2, kUnconfigured = 3, kWriteFailed = 4 };

struct RunSummary {
  RunOutcome outcome;
  StreamError stream_error;  // kBadStream: why
  uint32_t record_index;     // kBadStream: the record it happened at (1-based)
  uint16_t width, height;    // the header's frame size (kTooLarge: beyond kMaxColumns x kMaxRows)
  app::Counters counters;
  uint32_t watchdog_kicks;
  uint32_t gyro_dropped;
  protocol::ConfigField config_status;
};

// The DeviceInfo board name of both twins (QEMU and host): they are one
// device, and their report streams must be bit-identical.
constexpr const char* kStreamBoardName = "lumavel-stream";

// The protocol's default configuration (60 degrees, 8 cm) at the stream's
// working resolution: protocol::defaults_for with the default field of view.
protocol::DeviceConfig defaults_for(uint16_t width, uint16_t height);

// Not reentrant: the app (frame buffers, estimator) lives in static storage.
RunSummary run_stream(ByteSource& in, ByteSink& out, const char* board_name);

}  // namespace lumavel::stream
