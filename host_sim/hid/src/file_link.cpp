// file:PATH: input reports appended to a report-stream file.
#include <stdexcept>

#include "links.hpp"
#include "lumavel/host/hid_link.hpp"
#include "lumavel/host/report_file.hpp"

namespace lumavel::host {

namespace {

class FileLink : public hal::ReportLink {
 public:
  explicit FileLink(const std::string& path) : out_(path) {}
  ~FileLink() override { out_.flush(); }
  bool send_input(const uint8_t* report, size_t len) override { return out_.write(report, len); }
  void poll_features(FeatureHandler, void*) override {}  // nobody asks through a file

 private:
  ReportFileWriter out_;
};

}  // namespace

std::unique_ptr<hal::ReportLink> make_file_link(const std::string& path) {
  try {
    return std::make_unique<FileLink>(path);
  } catch (const std::runtime_error& e) {
    throw HidLinkError(std::string(e.what()) + " (check the directory exists and is writable)");
  }
}

}  // namespace lumavel::host
