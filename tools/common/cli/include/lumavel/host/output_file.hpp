// Output of a command that must not leave a misleading file behind: a regular
// file is written under a temporary name next to it and renamed into place
// only by commit(), so a failed run neither leaves a half-written CSV nor
// clobbers an earlier one. Standard output is gathered in an anonymous
// temporary file and copied out by commit(): a run that fails mid-way prints
// no header and no rows. Special files (/dev/null, pipes, symlinks) are
// written directly and never removed.
//
// The one place a tool's file is opened for writing and finished: every
// write error (a full disk, /dev/full, a file-size limit), at a write, at the
// flush or at the close, is reported as "FILE: write error: REASON" (the
// system's reason, e.g. "No space left on device", kept from the write that
// failed: stdio forgets it once its buffer is dropped).
#pragma once
#include <cstdio>
#include <string>

namespace lumavel::host {

namespace detail {
struct WriteChannel {  // where OutputFile's stream writes, and the first failure's errno
  int fd = -1;
  int error = 0;
};
}  // namespace detail

class OutputFile {
 public:
  enum class Placement {
    kReplaced,  // a regular file is written aside and moved into place by commit()
    kInPlace,   // written where it is, as it grows (a stream followed while it runs)
  };
  // "" means standard output. `what` names the output in messages ("the
  // CSV", "the plot"). Throws std::runtime_error "FILE: cannot create WHAT:
  // REASON".
  explicit OutputFile(const std::string& path, const std::string& what = "the output file",
                      Placement placement = Placement::kReplaced);
  ~OutputFile();  // without commit(): closes and removes the temporary file
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

  std::FILE* get() const { return file_; }
  bool is_stdout() const { return path_.empty(); }
  // Writes all of `text`; throws as check() does when it cannot.
  void write(const std::string& text);
  // Flushes; throws std::runtime_error "FILE: write error: REASON" when a
  // write so far failed. For an output written as it grows.
  void check();
  // check(), then closes and moves the file into place (copies it to
  // standard output). Throws std::runtime_error naming the file.
  void commit();

 private:
  [[noreturn]] void fail(int err);

  std::string path_, temp_;  // temp_ empty: written directly
  std::string name_;         // the file as messages name it
  std::FILE* raw_ = nullptr;   // the file opened (for standard output: the anonymous temporary file)
  std::FILE* file_ = nullptr;  // the stream the caller writes, which writes to raw_'s descriptor
  detail::WriteChannel channel_;
  bool committed_ = false;
};

// Writes `text` to `path` whole through an OutputFile (a regular file
// replaced only when all of it is written). Throws std::runtime_error
// "PATH: cannot create WHAT: REASON" or "PATH: write error: REASON".
void write_file(const std::string& path, const std::string& text, const std::string& what);

}  // namespace lumavel::host
