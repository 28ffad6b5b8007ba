// Host-side report links: the simulator (or a test feeder) plays the device
// side of lumavel's USB HID interface through one of these.
//   "uhid" or "uhid:/dev/uhid"   Linux uhid: a virtual HID device 1209:0001 that
//                                any hidapi (hidraw) program sees
//   "hidg" or "hidg:/dev/hidgN"  Linux USB gadget HID function (configfs), the
//                                device side of a real USB link
//   "file:PATH"                  report-stream file (report_file.hpp), for
//                                machines with neither; features are not served
#pragma once
#include <memory>
#include <stdexcept>
#include <string>

#include "lumavel/hal/report_link.hpp"

namespace lumavel::host {

// Opening failed; what() names the device and says what to do.
class HidLinkError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Throws HidLinkError for an unknown spec or a device that cannot be opened.
std::unique_ptr<hal::ReportLink> open_host_link(const std::string& spec);

// Why `spec` is not a link spec ("" when it is one): for command-line
// checks before anything is opened.
std::string check_host_link_spec(const std::string& spec);

// The accepted specs, for --help texts.
const char* host_link_help();

}  // namespace lumavel::host
