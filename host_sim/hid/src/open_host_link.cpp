#include "links.hpp"
#include "lumavel/host/hid_link.hpp"

namespace lumavel::host {

const char* host_link_help() {
  return "uhid[:/dev/uhid]   Linux uhid virtual HID device (needs the uhid module)\n"
         "hidg[:/dev/hidgN]  Linux USB gadget HID function (configfs gadget, see docs/usb-hid.md)\n"
         "file:PATH          report-stream file, read back with `lumavel-read replay PATH`\n";
}

std::unique_ptr<hal::ReportLink> open_host_link(const std::string& spec) {
  const size_t colon = spec.find(':');
  const std::string kind = spec.substr(0, colon);
  const std::string arg = colon == std::string::npos ? "" : spec.substr(colon + 1);
  if (kind == "uhid") return make_uhid_link(arg.empty() ? "/dev/uhid" : arg);
  if (kind == "hidg") return make_hidg_link(arg.empty() ? "/dev/hidg0" : arg);
  if (kind == "file") {
    if (arg.empty()) throw HidLinkError("--hid file: needs a path, e.g. file:run.hidrep");
    return make_file_link(arg);
  }
  throw HidLinkError("unknown HID link \"" + spec + "\"; use one of:\n" + host_link_help());
}

}  // namespace lumavel::host
