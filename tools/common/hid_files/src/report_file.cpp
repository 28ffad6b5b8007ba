#include "lumavel/host/report_file.hpp"

#include "lumavel/host/path_check.hpp"

#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace lumavel::host {

namespace {
constexpr size_t kMagicSize = sizeof(kReportFileMagic) - 1;
std::string why() { return std::strerror(errno); }
}  // namespace

ReportFileWriter::ReportFileWriter(const std::string& path) : f_(nullptr), path_(shown_path(path)) {
  std::string cannot;
  f_ = open_for_writing(path, "wb", cannot);
  if (f_ == nullptr) throw std::runtime_error(path_ + ": cannot create report file: " + cannot);
  if (std::fwrite(kReportFileMagic, 1, kMagicSize, f_) != kMagicSize) {
    std::fclose(f_);
    throw std::runtime_error(path_ + ": cannot write report file: " + why());
  }
}

ReportFileWriter::~ReportFileWriter() {
  if (f_ != nullptr) std::fclose(f_);
}

bool ReportFileWriter::write(const uint8_t* report, size_t len) {
  if (len == 0 || len > 255) return false;
  const uint8_t n = static_cast<uint8_t>(len);
  return std::fwrite(&n, 1, 1, f_) == 1 && std::fwrite(report, 1, len, f_) == len;
}

bool ReportFileWriter::flush() { return std::fflush(f_) == 0; }

ReportFileReader::ReportFileReader(const std::string& path) : f_(nullptr), path_(shown_path(path)) {
  // A FIFO is read as it is written (a live feed); folders and devices are refused.
  if (const std::string why = why_not_a_file(path, "report file"); !why.empty() && why.rfind("is a FIFO", 0) != 0)
    throw std::runtime_error(path_ + ": " + why);
  f_ = std::fopen(path.c_str(), "rb");
  if (f_ == nullptr) throw std::runtime_error(path_ + ": cannot open report file: " + why());
  char magic[kMagicSize];
  if (std::fread(magic, 1, kMagicSize, f_) != kMagicSize ||
      std::memcmp(magic, kReportFileMagic, kMagicSize) != 0) {
    std::fclose(f_);
    throw std::runtime_error(path_ + ": not a lumavel report file (no \"LMVHID1\" header)");
  }
}

ReportFileReader::~ReportFileReader() {
  if (f_ != nullptr) std::fclose(f_);
}

bool ReportFileReader::next(std::vector<uint8_t>& out) {
  const long at = std::ftell(f_);
  const int n = std::fgetc(f_);
  if (n == EOF) {
    if (std::ferror(f_)) throw std::runtime_error(path_ + ": read error: " + why());
    return false;
  }
  ++index_;
  offset_ = at;
  const std::string where = path_ + ": record " + std::to_string(index_) + " at byte " +
                            std::to_string(at);
  if (n == 0) throw std::runtime_error(where + ": zero-length record");
  out.resize(static_cast<size_t>(n));
  const size_t got = std::fread(out.data(), 1, out.size(), f_);
  if (got != out.size()) {
    throw std::runtime_error(where + ": truncated (" + std::to_string(got) + " of " +
                             std::to_string(n) + " bytes)");
  }
  return true;
}

}  // namespace lumavel::host
