// A lumavel HID device opened through hidapi: input reports, feature reports
// (GET_REPORT, or the mailbox where the device's USB stack cannot answer it).
#pragma once
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "hidapi_loader.hpp"
#include "lumavel/protocol/reports.hpp"

namespace lumavel::read {

// kNotHidraw: the --device path is something else (a file, /dev/null): no
// device will ever appear there, so `stream` does not wait for one.
enum class DeviceErrorKind { kNoDevice, kNotHidraw, kPermission, kGone, kProtocol, kIo };

class DeviceError : public std::runtime_error {
 public:
  DeviceError(DeviceErrorKind kind, const std::string& what) : std::runtime_error(what), kind_(kind) {}
  DeviceErrorKind kind() const { return kind_; }

 private:
  DeviceErrorKind kind_;
};

struct DeviceEntry {
  std::string path;
  uint16_t vid = 0, pid = 0;
  uint16_t usage_page = 0;
  int interface_number = -1;
  std::string manufacturer, product, serial;
};

// Every 1209:0001 device (usage page 0xFF00, or 0 where the backend does not
// report it: hidapi-libusb).
std::vector<DeviceEntry> list_devices(const HidApi& api);

// The message for a permission failure, with the udev rule to install.
std::string permission_help(const std::string& path);

class Device {
 public:
  // Opens `path`, or the first lumavel device when empty. Throws DeviceError.
  Device(const HidApi& api, const std::string& path);
  ~Device();
  Device(const Device&) = delete;
  Device& operator=(const Device&) = delete;

  // One input report: its length, 0 on timeout. Throws DeviceError(kGone).
  size_t read(uint8_t* buf, size_t cap, int timeout_ms);

  using Validator = std::function<protocol::DecodeResult(const uint8_t*, size_t)>;
  // Feature report `id`, validated. Throws DeviceError(kProtocol) naming the problem.
  std::vector<uint8_t> get_feature(uint8_t id, const Validator& valid);
  // Sends a feature report (ID first). Throws DeviceError if the device refuses it.
  void set_feature(const uint8_t* buf, size_t len);

  const std::string& path() const { return path_; }

 private:
  std::vector<uint8_t> get_through_mailbox(uint8_t id);
  std::string last_error() const;

  const HidApi& api_;
  hid_device* dev_ = nullptr;
  std::string path_;
  uint8_t next_tag_;  // mailbox request tag, one per request
};

}  // namespace lumavel::read
