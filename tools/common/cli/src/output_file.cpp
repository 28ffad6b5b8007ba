#include "lumavel/host/output_file.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

#include "lumavel/host/path_check.hpp"

namespace lumavel::host {

namespace {

// The caller's stream writes through here to the file's descriptor, so that
// the reason of a failed write is kept (stdio sets only an error flag, and
// errno is gone by the time the flag is looked at).
ssize_t write_to_channel(void* cookie, const char* buf, size_t n) {
  auto* ch = static_cast<detail::WriteChannel*>(cookie);
  size_t done = 0;
  while (done < n) {
    const ssize_t w = ::write(ch->fd, buf + done, n - done);
    if (w < 0 && errno == EINTR) continue;
    if (w <= 0) {
      if (ch->error == 0) ch->error = w < 0 ? errno : EIO;
      return -1;
    }
    done += static_cast<size_t>(w);
  }
  return static_cast<ssize_t>(n);
}

}  // namespace

OutputFile::OutputFile(const std::string& path, const std::string& what, Placement placement)
    : path_(path), name_(path.empty() ? std::string("standard output") : shown_path(path)) {
  std::string why;
  if (path.empty()) {
    raw_ = std::tmpfile();
    if (!raw_) why = std::strerror(errno);
  } else {
    // Anything that exists and is not a plain regular file (device, pipe, or
    // a symlink, which a rename would replace) is written in place.
    struct stat st {};
    const bool special = ::lstat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode);
    if (!special && placement == Placement::kReplaced) temp_ = temporary_name_for(path);
    raw_ = open_for_writing(temp_.empty() ? path : temp_, "w", why);
  }
  if (raw_) {
    channel_.fd = ::fileno(raw_);
    file_ = ::fopencookie(&channel_, "w", cookie_io_functions_t{nullptr, write_to_channel, nullptr, nullptr});
    if (!file_) {
      why = std::strerror(errno);
      std::fclose(raw_);
      if (!temp_.empty()) std::remove(temp_.c_str());
    }
  }
  if (!file_) throw std::runtime_error(name_ + ": cannot create " + what + ": " + why);
}

OutputFile::~OutputFile() {
  if (committed_) return;
  std::fclose(file_);
  std::fclose(raw_);
  if (!temp_.empty()) std::remove(temp_.c_str());
}

void OutputFile::fail(int err) {
  throw std::runtime_error(name_ + ": write error: " + std::strerror(err != 0 ? err : EIO));
}

void OutputFile::write(const std::string& text) {
  if (std::fwrite(text.data(), 1, text.size(), file_) != text.size()) check();
}

void OutputFile::check() {
  const bool flushed = std::fflush(file_) == 0;
  if (!flushed || std::ferror(file_) || channel_.error != 0) fail(channel_.error != 0 ? channel_.error : errno);
}

void OutputFile::commit() {
  check();
  committed_ = true;  // closed below either way
  std::fclose(file_);  // flushed: nothing left to write
  if (path_.empty()) {  // copy the gathered output to standard output
    std::rewind(raw_);
    char buf[1 << 16];
    size_t n = 0;
    bool ok = true;
    while (ok && (n = std::fread(buf, 1, sizeof buf, raw_)) > 0) ok = std::fwrite(buf, 1, n, stdout) == n;
    ok = ok && !std::ferror(raw_) && std::fflush(stdout) == 0;
    const int err = errno;
    std::fclose(raw_);
    if (!ok) fail(err);
    return;
  }
  // A close can fail too (a file system that reports at close, NFS).
  if (std::fclose(raw_) != 0) {
    const int err = errno;
    if (!temp_.empty()) std::remove(temp_.c_str());
    fail(err);
  }
  if (!temp_.empty() && std::rename(temp_.c_str(), path_.c_str()) != 0) {
    const int err = errno;
    std::remove(temp_.c_str());
    throw std::runtime_error(name_ + ": cannot move the output into place: " + std::strerror(err));
  }
}

void write_file(const std::string& path, const std::string& text, const std::string& what) {
  OutputFile out(path, what);
  out.write(text);
  out.commit();
}

}  // namespace lumavel::host
