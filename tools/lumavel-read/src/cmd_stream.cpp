// `stream` (live device) and `replay` (report file).
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdio>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <memory>
#include <thread>

#include "commands.hpp"
#include "device.hpp"
#include "lumavel/host/cli.hpp"
#include "lumavel/host/output_file.hpp"
#include "lumavel/host/path_check.hpp"
#include "lumavel/host/report_file.hpp"
#include "sink.hpp"

namespace lumavel::read {

namespace {

volatile std::sig_atomic_t g_stop = 0;
void on_signal(int) { g_stop = 1; }

// Where the CSV goes and whether the live line is drawn. A stream writes its
// file as reports arrive (it can be followed while it grows); a replay
// writes under a temporary name moved into place at the end, so that a
// refused or failed replay leaves no file behind.
struct Outputs {
  std::unique_ptr<host::OutputFile> file;  // -o FILE: in place (stream) or moved into place (replay)
  std::FILE* csv = nullptr;
  bool live = false;
  // A CSV file that could not be written (a full disk, /dev/full) throws
  // "FILE: write error: REASON" (was: stream went on, and ended in exit 3 'no
  // device' or 0, the loss unsaid).
  void check() const {
    if (file) file->check();
  }
};

void open_outputs(const StreamOptions& o, bool is_stream, Outputs& out) {
  const bool allow_live = is_stream;
  const bool tty = ::isatty(STDOUT_FILENO) != 0;
  const int forced = o.live ? 1 : o.no_live ? 0 : -1;
  if (!o.output.empty() && o.output != "-") {
    // A folder, or a name whose folder is missing, said as lumavel-sim's -o
    // says it (was: 'adir: cannot create the CSV: Is a directory', 'no/x.csv:
    // cannot create the CSV: No such file or directory').
    if (const std::string why = host::why_not_writable(o.output, "CSV file"); !why.empty())
      throw std::runtime_error(host::shown_path(o.output) + " (-o): " + why);
    // A FIFO nobody reads is refused after a short wait (fopen waited for ever).
    out.file = std::make_unique<host::OutputFile>(
        o.output, "the CSV", is_stream ? host::OutputFile::Placement::kInPlace : host::OutputFile::Placement::kReplaced);
    out.csv = out.file->get();
    out.live = forced == -1 ? tty : forced == 1;
  } else {
    const bool csv_to_stdout = !allow_live || !tty || o.csv_on_tty || forced == 0;
    out.csv = csv_to_stdout ? stdout : nullptr;
    out.live = forced == -1 ? !csv_to_stdout : (forced == 1 && !csv_to_stdout);
  }
  out.live = out.live && allow_live;
}

}  // namespace

int cmd_stream(const Common& c, const StreamOptions& o) {
  Outputs out;
  open_outputs(o, true, out);
  const HidApi& api = load_hidapi(c.backend_kind());
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
  Sink sink(out.csv, out.live);
  out.check();  // the header written before any device is looked for
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
      if (o.no_reconnect || timed_out() || e.kind() == DeviceErrorKind::kNotHidraw) {
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
        if (out.csv != nullptr && std::ferror(out.csv)) out.check();
      }
      if (timed_out()) {
        std::fprintf(stderr, "%sno report from %s for %.1f s: giving up\n", out.live ? "\n" : "",
                     dev->path().c_str(), o.timeout_s);
        status = kExitNoDevice;
        break;
      }
    } catch (const DeviceError& e) {
      std::fprintf(stderr, "%s%s\n", out.live ? "\n" : "", e.what());
      if (o.no_reconnect) {
        status = kExitNoDevice;
        break;
      }
      std::fprintf(stderr, "waiting for it to come back...\n");
      waiting_said = true;
    }
  }
  sink.finish();
  out.check();
  if (status == kExitOk && sink.malformed() > 0) status = kExitFailure;
  return status;
}

int cmd_replay(const std::string& file, const StreamOptions& o) {
  // The CSV written over the report file (or a link to it) would destroy
  // what is being read: refused before anything is written.
  if (!o.output.empty() && o.output != "-") {
    std::error_code ec;
    if (std::filesystem::equivalent(o.output, file, ec) && !ec)
      throw cli::UsageError(host::shown_path(o.output) + " (-o): that is the report file being read (" +
                            host::shown_path(file) + "); write the CSV elsewhere");
  }
  // Standard output the same: 'replay r.hid >> r.hid' appended the CSV to the
  // file as it was read, then read those lines as damaged records (the report
  // file lost, its own CSV reported as dozens of malformed reports).
  if (o.output.empty() || o.output == "-") {
    std::error_code ec;
    const std::string so = host::standard_output_file();
    if (!so.empty() && std::filesystem::equivalent(so, file, ec) && !ec)
      throw cli::UsageError(host::shown_path(so) + " (standard output): that is the report file being read (" +
                            host::shown_path(file) + "); write the CSV elsewhere");
  }
  // Opened after those checks: 'replay r.hid > r.hid' (the shell empties the
  // file before the tool starts) was 'not a lumavel report file (no "LMVHID1"
  // header)', as if the file had never been one.
  host::ReportFileReader in(file);  // a file that is not a report file is refused before any CSV is created
  Outputs out;
  open_outputs(o, false, out);
  Sink sink(out.csv, false, true);
  std::vector<uint8_t> rec;
  int status = kExitOk;
  try {
    while ((o.count == 0 || sink.measurements() < o.count) && in.next(rec))
      sink.take(rec.data(), rec.size(),
                "in " + host::shown_path(file) + " record " + std::to_string(in.record_index()) + " at byte " +
                    std::to_string(in.record_offset()));
  } catch (const std::runtime_error& e) {
    std::fprintf(stderr, "malformed report file %s\n", e.what());
    status = kExitFailure;
  }
  // A run sends a report for every frame pair, at least one: a file holding
  // its header alone was cut short (was: a CSV of the header line, exit 0).
  if (in.record_index() == 0)
    throw std::runtime_error(host::shown_path(file) + ": no record after its \"LMVHID1\" header: a run writes a report "
                             "for every frame pair, at least one (a file cut short?)");
  sink.finish();
  if (out.file) out.file->commit();  // the good reports of a damaged file are kept
  return sink.malformed() > 0 ? kExitFailure : status;
}

}  // namespace lumavel::read
