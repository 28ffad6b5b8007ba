// `stream` (live device) and `replay` (report file).
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <thread>

#include "commands.hpp"
#include "device.hpp"
#include "lumavel/host/report_file.hpp"
#include "sink.hpp"

namespace lumavel::read {

namespace {

volatile std::sig_atomic_t g_stop = 0;
void on_signal(int) { g_stop = 1; }

struct StreamOptions {
  std::string output;
  uint64_t count = 0;      // 0: until interrupted
  double timeout_s = 0;    // 0: wait forever
  bool reconnect = true;
  int live = -1;           // -1 auto (stdout is a terminal and CSV goes to a file)
  bool csv_on_tty = false;
};

bool parse_number(const std::string& s, double& out) {
  char* end = nullptr;
  out = std::strtod(s.c_str(), &end);
  return !s.empty() && *end == '\0' && out >= 0;
}

// Parses the options shared by stream and replay; returns false (with a message) on error.
bool parse_stream_options(const char* cmd, const std::vector<std::string>& args, StreamOptions& o,
                          std::vector<std::string>& positional) {
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    auto value = [&](std::string& v) {
      if (i + 1 >= args.size()) {
        std::fprintf(stderr, "lumavel-read %s: %s needs a value\n", cmd, a.c_str());
        return false;
      }
      v = args[++i];
      return true;
    };
    std::string v;
    double d = 0;
    if (a == "-o" || a == "--output") {
      if (!value(o.output)) return false;
    } else if (a == "-n" || a == "--count") {
      if (!value(v) || !parse_number(v, d)) {
        std::fprintf(stderr, "lumavel-read %s: --count needs a number\n", cmd);
        return false;
      }
      o.count = static_cast<uint64_t>(d);
    } else if (a == "--timeout") {
      if (!value(v) || !parse_number(v, d)) {
        std::fprintf(stderr, "lumavel-read %s: --timeout needs seconds\n", cmd);
        return false;
      }
      o.timeout_s = d;
    } else if (a == "--no-reconnect") {
      o.reconnect = false;
    } else if (a == "--live") {
      o.live = 1;
    } else if (a == "--no-live") {
      o.live = 0;
    } else if (a == "--csv") {
      o.csv_on_tty = true;
    } else if (!a.empty() && a[0] == '-') {
      std::fprintf(stderr, "lumavel-read %s: unknown option %s (see --help)\n", cmd, a.c_str());
      return false;
    } else {
      positional.push_back(a);
    }
  }
  return true;
}

// Opens the CSV destination and decides on the live view.
struct Outputs {
  std::FILE* csv = nullptr;
  bool own = false;
  bool live = false;
  ~Outputs() {
    if (own && csv != nullptr) std::fclose(csv);
  }
};

bool open_outputs(const char* cmd, const StreamOptions& o, Outputs& out) {
  const bool tty = ::isatty(STDOUT_FILENO) != 0;
  if (!o.output.empty()) {
    out.csv = std::fopen(o.output.c_str(), "w");
    if (out.csv == nullptr) {
      std::fprintf(stderr, "lumavel-read %s: cannot create %s\n", cmd, o.output.c_str());
      return false;
    }
    out.own = true;
    out.live = o.live == -1 ? tty : o.live == 1;
  } else {
    const bool csv_to_stdout = !tty || o.csv_on_tty || o.live == 0;
    out.csv = csv_to_stdout ? stdout : nullptr;
    out.live = o.live == -1 ? !csv_to_stdout : (o.live == 1 && !csv_to_stdout);
  }
  return true;
}

}  // namespace

int cmd_stream(const Common& c, const std::vector<std::string>& args) {
  if (wants_help(args)) {
    std::printf(
        "usage: lumavel-read [--backend B] [--device PATH] stream [options]\n"
        "Reads input reports and writes them as CSV (header: timestamp_ns,v_xb_mps,distance_m,\n"
        "heading_rad,status,gyro_offset_radps,frame_index,seq,overruns). When stdout is a terminal it shows a\n"
        "live line (rate, V, distance, heading, status) instead, unless --csv.\n"
        "  -o, --output FILE   write the CSV to FILE (live line on the terminal meanwhile)\n"
        "  -n, --count N       stop after N measurements\n"
        "  --timeout S         give up after S seconds without a report (default: never)\n"
        "  --no-reconnect      exit when the device goes away instead of waiting for it\n"
        "  --live / --no-live  force the live line on or off;  --csv  CSV even on a terminal\n"
        "Lost reports (sequence gaps) and malformed reports are reported on stderr; the exit\n"
        "status is 2 if any report was malformed, 3 if no device, 4 if permission denied.\n");
    return kExitOk;
  }
  StreamOptions o;
  std::vector<std::string> positional;
  if (!parse_stream_options("stream", args, o, positional)) return kExitUsage;
  if (!positional.empty()) {
    std::fprintf(stderr, "lumavel-read stream: unexpected argument \"%s\"\n", positional[0].c_str());
    return kExitUsage;
  }
  Outputs out;
  if (!open_outputs("stream", o, out)) return kExitUsage;
  const HidApi& api = load_hidapi(c.backend);
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
  Sink sink(out.csv, out.live);
  using Clock = std::chrono::steady_clock;
  auto last_data = Clock::now();
  auto timed_out = [&] {
    return o.timeout_s > 0 &&
           std::chrono::duration<double>(Clock::now() - last_data).count() > o.timeout_s;
  };
  bool waiting_said = false;
  int status = kExitOk;
  while (!g_stop && (o.count == 0 || sink.measurements() < o.count)) {
    std::unique_ptr<Device> dev;
    try {
      dev = std::make_unique<Device>(api, c.device);
    } catch (const DeviceError& e) {
      if (e.kind() == DeviceErrorKind::kPermission) {
        std::fprintf(stderr, "%s\n", e.what());
        return kExitPermission;
      }
      if (!o.reconnect || timed_out()) {
        std::fprintf(stderr, "%s\n", e.what());
        status = kExitNoDevice;
        break;
      }
      if (!waiting_said) std::fprintf(stderr, "%s\nwaiting for it...\n", e.what());
      waiting_said = true;
      std::this_thread::sleep_for(std::chrono::milliseconds(250));
      continue;
    }
    std::fprintf(stderr, "connected to %s\n", dev->path().c_str());
    waiting_said = false;
    sink.restart_sequence();
    try {
      uint8_t buf[256];
      while (!g_stop && (o.count == 0 || sink.measurements() < o.count)) {
        const size_t n = dev->read(buf, sizeof buf, 200);
        if (n == 0) {
          if (timed_out()) break;
          continue;
        }
        if (sink.take(buf, n, "from " + dev->path())) last_data = Clock::now();
      }
      if (timed_out()) {
        std::fprintf(stderr, "%sno report from %s for %.1f s: giving up\n", out.live ? "\n" : "",
                     dev->path().c_str(), o.timeout_s);
        status = kExitNoDevice;
        break;
      }
    } catch (const DeviceError& e) {
      std::fprintf(stderr, "%s%s\n", out.live ? "\n" : "", e.what());
      if (!o.reconnect) {
        status = kExitNoDevice;
        break;
      }
      std::fprintf(stderr, "waiting for it to come back...\n");
      waiting_said = true;
    }
  }
  sink.finish();
  if (status == kExitOk && sink.malformed() > 0) status = kExitMalformed;
  return status;
}

int cmd_replay(const Common&, const std::vector<std::string>& args) {
  if (wants_help(args)) {
    std::printf("usage: lumavel-read replay FILE [-o CSV]\n"
                "Decodes a report file (as written by `lumavel-sim run --hid file:FILE`) into the\n"
                "same CSV as `stream`. Malformed reports are named (record, byte offset) on stderr\n"
                "and make the exit status 2; the others are still written.\n");
    return kExitOk;
  }
  StreamOptions o;
  std::vector<std::string> positional;
  if (!parse_stream_options("replay", args, o, positional)) return kExitUsage;
  if (positional.size() != 1) {
    std::fprintf(stderr, "lumavel-read replay: give exactly one report file (see --help)\n");
    return kExitUsage;
  }
  o.live = 0;
  Outputs out;
  if (!open_outputs("replay", o, out)) return kExitUsage;
  host::ReportFileReader in(positional[0]);
  Sink sink(out.csv, false);
  std::vector<uint8_t> rec;
  try {
    while ((o.count == 0 || sink.measurements() < o.count) && in.next(rec)) {
    sink.take(rec.data(), rec.size(),
              "in " + positional[0] + " record " + std::to_string(in.record_index()) + " at byte " +
                  std::to_string(in.record_offset()));
    }
  } catch (const std::runtime_error& e) {
    sink.finish();
    std::fprintf(stderr, "malformed report file %s\n", e.what());
    return kExitMalformed;
  }
  sink.finish();
  return sink.malformed() > 0 ? kExitMalformed : kExitOk;
}

}  // namespace lumavel::read
