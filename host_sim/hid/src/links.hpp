// Constructors of the concrete host links (internal to lumavel_hid_host).
#pragma once
#include <memory>
#include <string>

#include "lumavel/hal/report_link.hpp"

namespace lumavel::host {

std::unique_ptr<hal::ReportLink> make_uhid_link(const std::string& path);
std::unique_ptr<hal::ReportLink> make_hidg_link(const std::string& path);
std::unique_ptr<hal::ReportLink> make_file_link(const std::string& path);

}  // namespace lumavel::host
