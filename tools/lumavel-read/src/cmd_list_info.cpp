// `list` and `info`.
#include <cstdio>
#include <cstring>

#include "commands.hpp"
#include "device.hpp"
#include "lumavel/protocol/device_config.hpp"
#include "lumavel/protocol/reports.hpp"

namespace lumavel::read {

namespace proto = lumavel::protocol;

int cmd_list(const Common& c) {
  const HidApi& api = load_hidapi(c.backend_kind());
  const auto found = list_devices(api);
  for (const DeviceEntry& e : found) {
    std::printf("%s  %04x:%04x  if %d  %s / %s / %s\n", e.path.c_str(), e.vid, e.pid,
                e.interface_number, e.manufacturer.empty() ? "-" : e.manufacturer.c_str(),
                e.product.empty() ? "-" : e.product.c_str(), e.serial.empty() ? "-" : e.serial.c_str());
  }
  if (found.empty()) {
    std::fprintf(stderr, "no lumavel device (1209:0001) found with the %s backend\n",
                 backend_name(c.backend_kind()));
    return kExitNoDevice;
  }
  return kExitOk;
}

int cmd_info(const Common& c) {
  Device dev(load_hidapi(c.backend_kind()), c.device);
  const auto raw = dev.get_feature(proto::kReportDeviceInfo, [](const uint8_t* b, size_t n) {
    proto::DeviceInfo d{};
    return proto::decode_device_info(b, n, d);
  });
  proto::DeviceInfo d{};
  proto::decode_device_info(raw.data(), raw.size(), d);
  static const char* kSource[] = {"defaults", "stored", "set by host"};
  static const char* kStaged[] = {"none", "cam0", "cam1", "cam0,cam1"};
  std::printf("device=%s\nfirmware=%u.%u.%u\nboard=%s\nresolution=%ux%u\n"
              "max_resolution=%ux%u\nmax_kernels=%u\nconfig_source=%s\nlast_config_set=%s\n"
              "last_lens_piece=%s\nlens_upload_pending=%s\n",
              dev.path().c_str(), d.fw_major, d.fw_minor, d.fw_patch, d.board, d.width, d.height,
              d.max_columns, d.max_rows, d.max_kernels, kSource[d.config_source],
              proto::to_string(static_cast<proto::ConfigField>(d.config_status)),
              proto::to_string(static_cast<proto::ConfigField>(d.lens_status)), kStaged[d.staged & 3u]);
  return kExitOk;
}

}  // namespace lumavel::read
