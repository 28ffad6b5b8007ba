// A stand-in hidapi backend whose one device is the firmware application
// itself (lumavel::app::App on HAL fakes), behind a link that can misbehave:
// drop chosen feature transfers (acknowledged but never delivered, as the
// Linux gadget does when the device is slow), go away after a number of
// transfers, answer GET_REPORT with zeros (the 6.1 gadget: feature reads go
// through the mailbox) and replay the previous mailbox answer for a report
// before each new one (a stale answer). For lumavel-read's command tests.
#pragma once
#include <cstdint>
#include <map>
#include <memory>
#include <set>
#include <vector>

#include "fake_hal.hpp"
#include "hidapi_loader.hpp"
#include "lumavel/app/app.hpp"

namespace lumavel::test {

class StandInDevice {
 public:
  StandInDevice();
  ~StandInDevice();
  StandInDevice(const StandInDevice&) = delete;
  StandInDevice& operator=(const StandInDevice&) = delete;

  // The HidApi that lumavel-read's commands will use (installed by the constructor).
  const read::HidApi& api() const { return api_; }
  app::App& app() { return *app_; }

  // Feature transfers are counted from 1 (sets and gets alike, mailbox
  // requests included). Those listed are acknowledged and lost.
  std::set<int> drop;
  // After this many transfers the device is gone (every call fails) until reconnect().
  int gone_after = -1;
  void reconnect() {
    gone_after = -1;
    gone_ = false;
  }
  bool gadget = false;       // GET_REPORT answers zeros: reads go through the mailbox
  bool replay_stale = false; // before each mailbox answer, the previous one for that report again
  int transfers() const { return transfers_; }

  // hidapi entry points (static: hidapi has no context pointer).
  static hid_device_info* enumerate(unsigned short, unsigned short);
  static void free_enumeration(hid_device_info*);
  static hid_device* open_path(const char*);
  static void close(hid_device*);
  static int read_timeout(hid_device*, unsigned char*, size_t, int);
  static int send_feature_report(hid_device*, const unsigned char*, size_t);
  static int get_feature_report(hid_device*, unsigned char*, size_t);
  static const wchar_t* error(hid_device*);

 private:
  bool transfer();  // counts one; false if dropped or gone
  void frame();     // one app frame: serves pending requests, sends reports

  fake::Camera camera_;
  fake::Gyro gyro_;
  fake::Clock clock_;
  fake::Link link_;
  fake::Store store_;
  fake::Watchdog watchdog_;
  std::unique_ptr<app::App> app_;
  read::HidApi api_{};
  int transfers_ = 0;
  bool gone_ = false;
  size_t next_input_ = 0;
  std::map<uint8_t, std::vector<std::vector<uint8_t>>> last_answer_;  // mailbox chunks, per report
};

}  // namespace lumavel::test
