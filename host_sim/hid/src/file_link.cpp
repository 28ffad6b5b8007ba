// file:PATH: input reports appended to a report-stream file.
//
// Complete or absent, like `run -o`: the reports go to PATH.tmpPID-N and the
// file is moved to PATH only when the link is closed normally; a run that
// fails mid-way (the link destroyed while an exception unwinds) removes it,
// so `lumavel-read replay` never reads half a run as if it were whole.
// Anything at PATH that is not a regular file (a FIFO, /dev/null, a symlink)
// is written in place.
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>
#include <memory>
#include <stdexcept>

#include "links.hpp"
#include "lumavel/host/hid_link.hpp"
#include "lumavel/host/path_check.hpp"
#include "lumavel/host/report_file.hpp"

namespace lumavel::host {

namespace {

bool is_special(const std::string& path) {
  struct stat st {};
  return ::lstat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode);
}

class FileLink : public hal::ReportLink {
 public:
  explicit FileLink(const std::string& path)
      : path_(path),
        temp_(is_special(path) ? std::string() : temporary_name_for(path)),
        out_(std::make_unique<ReportFileWriter>(temp_.empty() ? path_ : temp_)),
        exceptions_(std::uncaught_exceptions()) {}
  ~FileLink() override {
    const bool failed = std::uncaught_exceptions() > exceptions_;
    const bool written = out_->flush();
    out_.reset();  // closed before the rename
    if (temp_.empty()) return;
    if (failed || !written || std::rename(temp_.c_str(), path_.c_str()) != 0) std::remove(temp_.c_str());
  }
  // Each report is flushed: a write error (a full disk, /dev/full) ends the
  // run with its cause instead of passing for an overrun or a silent loss.
  bool send_input(const uint8_t* report, size_t len) override {
    if (!out_->write(report, len) || !out_->flush())
      throw HidLinkError(path_ + ": cannot write the report file: " + std::strerror(errno));
    return true;
  }
  void poll_features(FeatureHandler, void*) override {}  // nobody asks through a file

 private:
  std::string path_, temp_;  // temp_ empty: written in place
  std::unique_ptr<ReportFileWriter> out_;
  int exceptions_;  // std::uncaught_exceptions() when opened
};

}  // namespace

std::unique_ptr<hal::ReportLink> make_file_link(const std::string& path) {
  try {
    return std::make_unique<FileLink>(path);
  } catch (const std::runtime_error& e) {
    // Its reason says why already (a FIFO nobody reads, the system's error);
    // run refuses a folder that does not exist before it gets here.
    throw HidLinkError(e.what());
  }
}

}  // namespace lumavel::host
