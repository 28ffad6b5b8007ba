// Output of a command that must not leave a misleading file behind: a regular
// file is written under a temporary name next to it and renamed into place
// only by commit(), so a failed run neither leaves a half-written CSV nor
// clobbers an earlier one. Special files (/dev/null, pipes, symlinks) and
// standard output are written directly and never removed.
#pragma once
#include <cstdio>
#include <string>

namespace lumavel::host {

class OutputFile {
 public:
  // "" means standard output. Throws std::runtime_error naming the file.
  explicit OutputFile(const std::string& path);
  ~OutputFile();  // without commit(): closes and removes the temporary file
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

  std::FILE* get() const { return file_; }
  // Flushes, checks for write errors and moves the file into place. Throws
  // std::runtime_error naming the file.
  void commit();

 private:
  std::string path_, temp_;  // temp_ empty: written directly
  std::FILE* file_ = nullptr;
  bool committed_ = false;
};

}  // namespace lumavel::host
