#include "lumavel/host/output_file.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

#include "lumavel/host/path_check.hpp"

namespace lumavel::host {

OutputFile::OutputFile(const std::string& path) : path_(path) {
  if (path.empty()) {
    file_ = std::tmpfile();
    if (!file_) throw std::runtime_error(std::string("standard output: cannot create its temporary file: ") +
                                         std::strerror(errno));
    return;
  }
  // Anything that exists and is not a plain regular file (device, pipe, or a
  // symlink, which a rename would replace) is written in place.
  struct stat st {};
  const bool special = ::lstat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode);
  if (!special) temp_ = path + ".tmp" + std::to_string(::getpid());
  std::string why;
  file_ = open_for_writing(special ? path : temp_, "w", why);
  if (!file_) throw std::runtime_error(path + ": cannot create the output file: " + why);
}

OutputFile::~OutputFile() {
  if (committed_) return;
  std::fclose(file_);
  if (!temp_.empty()) std::remove(temp_.c_str());
}

void OutputFile::commit() {
  const std::string name = path_.empty() ? std::string("standard output") : path_;
  if (std::fflush(file_) != 0 || std::ferror(file_)) throw std::runtime_error(name + ": write error");
  if (path_.empty()) {  // copy the gathered output to standard output
    std::rewind(file_);
    char buf[1 << 16];
    size_t n = 0;
    bool ok = true;
    while (ok && (n = std::fread(buf, 1, sizeof buf, file_)) > 0) ok = std::fwrite(buf, 1, n, stdout) == n;
    ok = ok && !std::ferror(file_);
    std::fclose(file_);
    committed_ = true;
    if (!ok || std::fflush(stdout) != 0) throw std::runtime_error(name + ": write error");
    return;
  }
  const int closed = std::fclose(file_);
  committed_ = true;  // closed either way
  if (closed != 0) {
    if (!temp_.empty()) std::remove(temp_.c_str());
    throw std::runtime_error(name + ": write error");
  }
  if (!temp_.empty() && std::rename(temp_.c_str(), path_.c_str()) != 0) {
    const int err = errno;
    std::remove(temp_.c_str());
    throw std::runtime_error(name + ": cannot move the output into place: " + std::strerror(err));
  }
}

}  // namespace lumavel::host
