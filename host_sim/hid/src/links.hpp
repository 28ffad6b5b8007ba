// Constructors of the concrete host links (internal to lumavel_hid_host).
#pragma once
#include <memory>
#include <string>

#include "lumavel/hal/report_link.hpp"

namespace lumavel::host {

std::unique_ptr<hal::ReportLink> make_uhid_link(const std::string& path);
std::unique_ptr<hal::ReportLink> make_hidg_link(const std::string& path);
std::unique_ptr<hal::ReportLink> make_file_link(const std::string& path);

// uhid and hidg write their events and reports to a device node: a regular
// file there was written over (and uhid then waited for kernel events that a
// file never gives: a hang). Throws HidLinkError naming the path and what it
// is, before it is opened; a missing path is left to open's own message.
// Where sysfs says what a device node is, it must be of that `subsystem`
// and, given one, have that `name` (another device, /dev/zero, is refused).
void refuse_if_not_a_device(const std::string& path, const std::string& what, const std::string& subsystem,
                            const std::string& name);

}  // namespace lumavel::host
