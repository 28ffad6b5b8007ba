#include "hidraw_path.hpp"

#include <sys/stat.h>
#include <sys/sysmacros.h>

#include <cerrno>
#include <cstring>

#include "lumavel/host/path_check.hpp"

namespace lumavel::read {
namespace {

constexpr const char* kHint = " (use a path that `lumavel-read list` shows, such as /dev/hidraw0)";

}  // namespace

std::string why_not_hidraw(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) {
    if (errno == ENOENT) return "";
    return path + ": " + std::strerror(errno) + kHint;
  }
  if (S_ISREG(st.st_mode)) return path + " is a regular file, not a hidraw device" + kHint;
  if (S_ISDIR(st.st_mode)) return path + " is a directory, not a hidraw device" + kHint;
  if (!S_ISCHR(st.st_mode)) return path + " is not a character device, so not a hidraw device" + kHint;
  const std::string sub = host::char_device_of(path).subsystem;
  if (sub == "hidraw") return "";
  return path + " is the character device " + std::to_string(major(st.st_rdev)) + ":" +
         std::to_string(minor(st.st_rdev)) + (sub.empty() ? "" : " (" + sub + ")") + ", not a hidraw device" + kHint;
}

}  // namespace lumavel::read
