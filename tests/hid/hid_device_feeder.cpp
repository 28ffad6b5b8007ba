// Device side of the HID end-to-end test: serves an estimates CSV (or a report
// file) as lumavel input reports through a host link (uhid, hidg, file), and
// answers the feature reports (info, config get/set with a file-backed store)
// through app::FeatureServer, as the firmware does.
#include <csignal>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "estimates_csv.hpp"
#include "lumavel/app/feature_server.hpp"
#include "lumavel/host/file_config_store.hpp"
#include "lumavel/host/hid_link.hpp"
#include "lumavel/host/report_file.hpp"
#include "lumavel/protocol/descriptor.hpp"

namespace proto = lumavel::protocol;
using Clock = std::chrono::steady_clock;

namespace {

volatile std::sig_atomic_t g_stop = 0;
void on_signal(int) { g_stop = 1; }

void usage() {
  std::printf(
      "usage: hid_device_feeder --link SPEC (--estimates CSV | --reports FILE) [options]\n"
      "       hid_device_feeder --write-descriptor FILE\n"
      "  --link SPEC        uhid | hidg:/dev/hidgN | file:PATH\n"
      "  --period-us N      pacing between input reports (default 2000)\n"
      "  --store FILE       configuration store (default: none, nothing persists)\n"
      "  --wait-ms N        give up when the host takes no report for N ms (default 60000)\n"
      "  --linger-ms N      keep serving feature reports N ms after the last report\n"
      "                     (-1: until SIGTERM; default 0)\n");
}

proto::ConfigField accept_all(void*, const proto::DeviceConfig&, const lumavel::EdgeOffsetQ15* const[2]) {
  return proto::ConfigField::kOk;
}

}  // namespace

int main(int argc, char** argv) {
  std::string link_spec, estimates, reports, store_path;
  long period_us = 2000, wait_ms = 60000, linger_ms = 0;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto next = [&]() -> std::string {
      if (i + 1 >= argc) {
        std::fprintf(stderr, "hid_device_feeder: %s needs a value\n", a.c_str());
        std::exit(1);
      }
      return argv[++i];
    };
    if (a == "-h" || a == "--help") {
      usage();
      return 0;
    } else if (a == "--write-descriptor") {
      const std::string path = next();
      std::FILE* f = std::fopen(path.c_str(), "wb");
      if (f == nullptr || std::fwrite(proto::kReportDescriptor, 1, proto::kReportDescriptorSize, f) !=
                              proto::kReportDescriptorSize) {
        std::fprintf(stderr, "hid_device_feeder: cannot write %s\n", path.c_str());
        return 1;
      }
      std::fclose(f);
      return 0;
    } else if (a == "--link") link_spec = next();
    else if (a == "--estimates") estimates = next();
    else if (a == "--reports") reports = next();
    else if (a == "--store") store_path = next();
    else if (a == "--period-us") period_us = std::strtol(next().c_str(), nullptr, 10);
    else if (a == "--wait-ms") wait_ms = std::strtol(next().c_str(), nullptr, 10);
    else if (a == "--linger-ms") linger_ms = std::strtol(next().c_str(), nullptr, 10);
    else {
      std::fprintf(stderr, "hid_device_feeder: unknown argument %s\n", a.c_str());
      usage();
      return 1;
    }
  }
  if (link_spec.empty() || estimates.empty() == reports.empty()) {
    usage();
    return 1;
  }
  try {
    std::vector<std::vector<uint8_t>> out;
    if (!estimates.empty()) {
      for (const proto::Measurement& m : lumavel::test::read_estimates_csv(estimates)) {
        std::vector<uint8_t> r(proto::kMeasurementSize);
        proto::encode_measurement(m, r.data(), r.size());
        out.push_back(r);
      }
    } else {
      lumavel::host::ReportFileReader in(reports);
      std::vector<uint8_t> r;
      while (in.next(r)) out.push_back(r);
    }
    std::signal(SIGTERM, on_signal);
    std::signal(SIGINT, on_signal);
    auto link = lumavel::host::open_host_link(link_spec);

    proto::DeviceInfo id{};
    id.fw_major = 0;
    id.fw_minor = 1;
    id.fw_patch = 0;
    std::strncpy(id.board, "host-feeder", proto::kBoardNameSize);
    id.max_columns = lumavel::kMaxColumns;
    id.max_rows = lumavel::kMaxRows;
    id.max_kernels = lumavel::kMaxKernels;
    lumavel::host::FileConfigStore file_store(store_path);
    lumavel::app::FeatureServer server(id, store_path.empty() ? nullptr : &file_store, accept_all, nullptr);
    server.boot(proto::default_device_config());

    auto serve = [&] { link->poll_features(&lumavel::app::FeatureServer::handle, &server); };
    size_t sent = 0;
    for (const auto& r : out) {
      const auto deadline = Clock::now() + std::chrono::milliseconds(wait_ms);
      while (!link->send_input(r.data(), r.size())) {
        serve();
        if (g_stop) return 1;
        if (Clock::now() > deadline) {
          std::fprintf(stderr, "hid_device_feeder: no host took report %zu of %zu within %ld ms\n",
                       sent + 1, out.size(), wait_ms);
          return 1;
        }
        std::this_thread::sleep_for(std::chrono::microseconds(200));
      }
      ++sent;
      serve();
      std::this_thread::sleep_for(std::chrono::microseconds(period_us));
    }
    std::fprintf(stderr, "hid_device_feeder: sent %zu reports through %s\n", sent, link_spec.c_str());
    const auto end = Clock::now() + std::chrono::milliseconds(linger_ms < 0 ? 0 : linger_ms);
    while (!g_stop && (linger_ms < 0 || Clock::now() < end)) {
      serve();
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "hid_device_feeder: %s\n", e.what());
    return 1;
  }
}
