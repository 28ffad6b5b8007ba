#include "device.hpp"

#include <unistd.h>

#include <chrono>
#include <random>

#include "hidraw_path.hpp"
#include "lumavel/protocol/descriptor.hpp"

namespace lumavel::read {

namespace proto = lumavel::protocol;

namespace {

bool mentions_permission(const std::string& s) {
  return s.find("ermission") != std::string::npos || s.find("ACCESS") != std::string::npos ||
         s.find("Access denied") != std::string::npos;
}

}  // namespace

std::string permission_help(const std::string& path) {
  return "permission denied opening " + path +
         " (lumavel 1209:0001).\n"
         "Install the udev rule that gives the logged-in user access, then replug the device:\n"
         "  sudo install -m 644 tools/udev/70-lumavel.rules /etc/udev/rules.d/\n"
         "  sudo udevadm control --reload-rules && sudo udevadm trigger\n"
         "(or run as root).";
}

std::vector<DeviceEntry> list_devices(const HidApi& api) {
  std::vector<DeviceEntry> out;
  hid_device_info* all = api.enumerate(proto::kUsbVendorId, proto::kUsbProductId);
  for (hid_device_info* d = all; d != nullptr; d = d->next) {
    if (d->usage_page != 0 && d->usage_page != proto::kUsagePage) continue;
    DeviceEntry e;
    e.path = d->path != nullptr ? d->path : "";
    e.vid = d->vendor_id;
    e.pid = d->product_id;
    e.usage_page = d->usage_page;
    e.interface_number = d->interface_number;
    e.manufacturer = narrow(d->manufacturer_string);
    e.product = narrow(d->product_string);
    e.serial = narrow(d->serial_number);
    out.push_back(e);
  }
  api.free_enumeration(all);
  return out;
}

Device::Device(const HidApi& api, const std::string& path)
    : api_(api),
      path_(path),
      // Start where another process's recent requests are unlikely to be.
      next_tag_(static_cast<uint8_t>(std::random_device{}())) {
  // A path given by the user goes to the hidraw backend only when it is a
  // hidraw node (hidraw_path.hpp); enumerated paths come from hidapi itself.
  if (!path_.empty() && api.backend == Backend::kHidraw) {
    const std::string why = why_not_hidraw(path_);
    if (!why.empty()) throw DeviceError(DeviceErrorKind::kNotHidraw, why);
  }
  if (path_.empty()) {
    const std::vector<DeviceEntry> found = list_devices(api);
    if (found.empty()) {
      throw DeviceError(DeviceErrorKind::kNoDevice,
                        std::string("no lumavel device (USB 1209:0001) found with the ") +
                            backend_name(api.backend) +
                            " backend: is it plugged in? (`lumavel-read list` shows what is seen)");
    }
    path_ = found.front().path;
  }
  dev_ = api.open_path(path_.c_str());
  if (dev_ == nullptr) {
    const std::string err = narrow(api.error(nullptr));
    const bool denied = mentions_permission(err) ||
                        (path_.rfind("/dev/", 0) == 0 && ::access(path_.c_str(), R_OK | W_OK) != 0 &&
                         ::access(path_.c_str(), F_OK) == 0);
    if (denied) throw DeviceError(DeviceErrorKind::kPermission, permission_help(path_));
    throw DeviceError(DeviceErrorKind::kNoDevice,
                      "cannot open lumavel device " + path_ + (err.empty() ? "" : ": " + err));
  }
}

Device::~Device() {
  if (dev_ != nullptr) api_.close(dev_);
}

std::string Device::last_error() const { return narrow(api_.error(dev_)); }

size_t Device::read(uint8_t* buf, size_t cap, int timeout_ms) {
  const int n = api_.read_timeout(dev_, buf, cap, timeout_ms);
  if (n < 0) {
    throw DeviceError(DeviceErrorKind::kGone, "lumavel device " + path_ + " went away (" +
                                                  last_error() + ")");
  }
  return static_cast<size_t>(n);  // 0: timeout, or a zero-length packet (libusb): no data
}

std::vector<uint8_t> Device::get_feature(uint8_t id, const Validator& valid) {
  std::vector<uint8_t> buf(proto::kMaxReportSize + 1, 0);
  buf[0] = id;
  const int n = api_.get_feature_report(dev_, buf.data(), buf.size());
  if (n > 0) {
    buf.resize(static_cast<size_t>(n));
    if (valid(buf.data(), buf.size()).ok()) return buf;
  }
  // No valid answer to GET_REPORT: a stack that cannot forward it (Linux
  // gadget HID) answers zeros. Ask through the mailbox.
  std::vector<uint8_t> got = get_through_mailbox(id);
  const proto::DecodeResult r = valid(got.data(), got.size());
  if (!r.ok()) {
    throw DeviceError(DeviceErrorKind::kProtocol,
                      "malformed feature report " + std::to_string(id) + " from " + path_ + ": " +
                          proto::to_string(r.error) + (*r.field ? std::string(" (") + r.field + ")" : ""));
  }
  return got;
}

std::vector<uint8_t> Device::get_through_mailbox(uint8_t id) {
  // A fresh tag per request: chunks of an earlier answer (a request that
  // timed out, or another process's) are skipped, never taken as current.
  const uint8_t tag = next_tag_++;
  uint8_t req[proto::kMailboxSize];
  proto::encode_mailbox_request(id, tag, req, sizeof req);
  if (api_.send_feature_report(dev_, req, sizeof req) < 0) {
    throw DeviceError(DeviceErrorKind::kProtocol, "lumavel device " + path_ +
                                                      " answered neither GET_REPORT nor the mailbox (" +
                                                      last_error() + ")");
  }
  std::vector<uint8_t> out;
  std::vector<bool> have;
  size_t missing = 1;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(2);
  uint8_t buf[256];
  while (missing > 0 && std::chrono::steady_clock::now() < deadline) {
    const size_t n = read(buf, sizeof buf, 100);
    proto::FeatureChunk c{};
    if (n == 0 || buf[0] != proto::kReportFeatureChunk) continue;  // measurements meanwhile
    if (!proto::decode_feature_chunk(buf, n, c).ok() || c.report_id != id || c.tag != tag) continue;
    if (out.empty()) {
      out.assign(c.total, 0);
      have.assign(c.total, false);
      missing = c.total;
    }
    if (c.total != out.size()) continue;
    for (size_t i = 0; i < c.length; ++i) {
      if (!have[c.offset + i]) --missing;
      have[c.offset + i] = true;
      out[c.offset + i] = c.data[i];
    }
  }
  if (missing > 0) {
    throw DeviceError(DeviceErrorKind::kProtocol,
                      "no reply from lumavel device " + path_ + " for feature report " +
                          std::to_string(id) + " within 2 s");
  }
  return out;
}

void Device::set_feature(const uint8_t* buf, size_t len) {
  if (api_.send_feature_report(dev_, buf, len) < 0) {
    throw DeviceError(DeviceErrorKind::kProtocol,
                      "lumavel device " + path_ + " refused feature report " +
                          std::to_string(buf[0]) + " (" + last_error() + ")");
  }
}

}  // namespace lumavel::read
