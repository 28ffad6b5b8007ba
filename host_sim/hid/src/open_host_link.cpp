#include "links.hpp"
#include "lumavel/host/hid_link.hpp"
#include "lumavel/host/path_check.hpp"

namespace lumavel::host {

const char* host_link_help() {
  return "uhid[:/dev/uhid]   Linux uhid virtual HID device (needs the uhid module)\n"
         "hidg[:/dev/hidgN]  Linux USB gadget HID function (configfs gadget, see docs/usb-hid.md)\n"
         "file:PATH          report-stream file, read back with `lumavel-read replay PATH`\n";
}

namespace {

struct LinkSpec {
  std::string kind, arg;
};

LinkSpec split(const std::string& spec) {
  const size_t colon = spec.find(':');
  return {spec.substr(0, colon), colon == std::string::npos ? "" : spec.substr(colon + 1)};
}

}  // namespace

void refuse_if_not_a_device(const std::string& path, const std::string& what, const std::string& subsystem,
                            const std::string& name) {
  if (!path_present(path)) return;
  if (const std::string why = why_not_a_device(path, what, subsystem, name); !why.empty())
    throw HidLinkError(path + ": " + why + "; a report file is --hid file:PATH");
}

std::string check_host_link_spec(const std::string& spec) {
  const LinkSpec s = split(spec);
  if (s.kind == "uhid" || s.kind == "hidg") return {};
  if (s.kind == "file") return s.arg.empty() ? "file: needs a path, e.g. file:run.hidrep" : "";
  return "unknown HID link \"" + spec + "\"; use one of:\n" + host_link_help();
}

std::unique_ptr<hal::ReportLink> open_host_link(const std::string& spec) {
  const std::string bad = check_host_link_spec(spec);
  if (!bad.empty()) throw HidLinkError(bad);
  const LinkSpec s = split(spec);
  if (s.kind == "uhid") return make_uhid_link(s.arg.empty() ? "/dev/uhid" : s.arg);
  if (s.kind == "hidg") return make_hidg_link(s.arg.empty() ? "/dev/hidg0" : s.arg);
  return make_file_link(s.arg);
}

}  // namespace lumavel::host
