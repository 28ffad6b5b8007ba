#include "lumavel/stream/run_stream.hpp"

#include "lumavel/board/static_object.hpp"

namespace lumavel::stream {

protocol::DeviceConfig defaults_for(uint16_t width, uint16_t height) { return protocol::defaults_for(width, height); }

RunSummary run_stream(ByteSource& in, ByteSink& out, const char* board_name) {
  RunSummary s{};
  StreamReader reader(in);
  const bool opened = reader.open();
  s.width = reader.width();
  s.height = reader.height();
  if (!opened) {
    s.outcome = RunOutcome::kBadStream;
    s.stream_error = reader.error();
    return s;
  }
  StreamCamera camera(reader);
  StreamGyro gyro(reader);
  StreamClock clock(camera);
  StreamReportLink link(reader, out);
  RamConfigStore store;
  CountingWatchdog watchdog;
  static board::StaticObject<app::App> storage;
  app::App& a = storage.emplace(app::Hal{camera, gyro, clock, link, store, watchdog},
                                app::Board{board_name, defaults_for(reader.width(), reader.height())});
  const bool configured = a.start();
  if (configured) a.run();
  s.counters = a.counters();
  s.watchdog_kicks = watchdog.kicks();
  s.gyro_dropped = reader.gyro_dropped();
  s.config_status = a.config_status();
  s.stream_error = reader.error();
  s.record_index = reader.record_index();
  if (!configured) {
    s.outcome = RunOutcome::kUnconfigured;
  } else if (reader.error() != StreamError::kNone) {
    s.outcome = RunOutcome::kBadStream;
  } else if (link.write_failed()) {
    s.outcome = RunOutcome::kWriteFailed;
  } else {
    s.outcome = RunOutcome::kOk;
  }
  return s;
}

}  // namespace lumavel::stream
