// The report-stream file: what `file:PATH` links write and `lumavel-read
// replay` reads. Raw reports exactly as they travel over USB.
//   8-byte magic "LMVHID1\n", then records: 1 length byte (1..255) followed by
//   that many report bytes (report ID first).
#pragma once
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

namespace lumavel::host {

constexpr char kReportFileMagic[] = "LMVHID1\n";  // 8 bytes without the NUL

class ReportFileWriter {
 public:
  // Throws std::runtime_error naming the file if it cannot be created.
  explicit ReportFileWriter(const std::string& path);
  ~ReportFileWriter();
  ReportFileWriter(const ReportFileWriter&) = delete;
  ReportFileWriter& operator=(const ReportFileWriter&) = delete;
  // False on a write error or a length outside 1..255.
  bool write(const uint8_t* report, size_t len);
  bool flush();

 private:
  std::FILE* f_;
  std::string path_;  // as messages show it (shown_path): a name given on the command line
};

class ReportFileReader {
 public:
  // Throws std::runtime_error naming the file if it cannot be opened or has no magic.
  explicit ReportFileReader(const std::string& path);
  ~ReportFileReader();
  ReportFileReader(const ReportFileReader&) = delete;
  ReportFileReader& operator=(const ReportFileReader&) = delete;
  // Next record into `out`. False at a clean end of file; throws
  // std::runtime_error naming file, record and byte offset for a truncated
  // or zero-length record.
  bool next(std::vector<uint8_t>& out);
  size_t record_index() const { return index_; }  // 1-based index of the last record read
  long record_offset() const { return offset_; }  // byte offset of the last record read

 private:
  std::FILE* f_;
  std::string path_;  // as messages show it (shown_path): a name given on the command line
  size_t index_ = 0;
  long offset_ = 0;
};

}  // namespace lumavel::host
