// Output of a command that must not leave a misleading file behind: a regular
// file is written under a temporary name next to it and renamed into place
// only by commit(), so a failed run neither leaves a half-written CSV nor
// clobbers an earlier one. Standard output is gathered in an anonymous
// temporary file and copied out by commit(): a run that fails mid-way prints
// no header and no rows. Special files (/dev/null, pipes, symlinks) are
// written directly and never removed.
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
  bool is_stdout() const { return path_.empty(); }
  // Flushes, checks for write errors and moves the file into place. Throws
  // std::runtime_error naming the file.
  void commit();

 private:
  std::string path_, temp_;  // temp_ empty: written directly
  std::FILE* file_ = nullptr;  // for standard output: the anonymous temporary file
  bool committed_ = false;
};

}  // namespace lumavel::host
