#include "lumavel/host/path_check.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <climits>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <thread>

namespace lumavel::host {
namespace {

// Where the symbolic link `path` leads, through any links after it, when
// nothing is there (a dangling link); "" when `path` is no symbolic link.
std::string dangling_link_target(const std::string& path) {
  namespace fs = std::filesystem;
  struct stat st {};
  fs::path p = path;
  for (int hops = 0; ::lstat(p.c_str(), &st) == 0 && S_ISLNK(st.st_mode); ++hops) {
    std::error_code ec;
    const fs::path to = fs::read_symlink(p, ec);
    if (ec || hops == 40) return "";  // unreadable, or a loop (stat says ELOOP for that)
    p = to.is_absolute() ? to : p.parent_path() / to;
  }
  return p == fs::path(path) ? "" : p.lexically_normal().string();
}

// The reason stat() of `path` failed with `err`, in words.
std::string stat_failure(const std::string& path, int err) {
  switch (err) {
    case ENOENT: {
      // A link to a moved file is something there, not nothing: said as what it is.
      const std::string to = dangling_link_target(path);
      return to.empty() ? "does not exist" : "is a symbolic link to " + shown_path(to) + ", which does not exist";
    }
    case ENOTDIR: return "does not exist (a part of the path before it is a file, not a folder)";
    case ELOOP: return "is a loop of symbolic links (or the path has too many of them)";
    case ENAMETOOLONG:
      return "the path is too long for the system (at most " + std::to_string(PATH_MAX) +
             " characters, and " + std::to_string(NAME_MAX) + " per name)";
    case EACCES: return "cannot be reached: permission denied on a folder of its path";
    default: return std::string("cannot be examined: ") + std::strerror(err);
  }
}

// What the file type is, for "is a ..., not a ..." (never a regular file or folder).
const char* special_kind(mode_t mode) {
  if (S_ISFIFO(mode)) return "a FIFO (named pipe)";
  if (S_ISCHR(mode)) return "a character device node";
  if (S_ISBLK(mode)) return "a block device node";
  if (S_ISSOCK(mode)) return "a socket";
  return "a special file";
}

// The length of the UTF-8 sequence at s[i] if it is valid and visible, else 0.
// Bytes that are no character, C1 controls (U+0080..U+009F: U+009B is CSI to
// a terminal) and the invisible format characters (a byte-order mark inside a
// line, zero-width spaces, bidirectional overrides that reorder what follows)
// are shown as \xNN: a key that began with a BOM read 'unknown configuration
// key "height"', and a binary file's bytes went to the terminal as they were.
size_t visible_utf8(const std::string& s, size_t i) {
  const auto b = [&](size_t k) { return static_cast<unsigned char>(s[k]); };
  const unsigned char c = b(i);
  const size_t n = c >= 0xF0 && c <= 0xF4 ? 4 : c >= 0xE0 ? 3 : c >= 0xC2 && c < 0xE0 ? 2 : 0;
  if (n == 0 || i + n > s.size()) return 0;
  uint32_t cp = c & (n == 2 ? 0x1F : n == 3 ? 0x0F : 0x07);
  for (size_t k = 1; k < n; ++k) {
    if ((b(i + k) & 0xC0) != 0x80) return 0;
    cp = (cp << 6) | (b(i + k) & 0x3F);
  }
  const uint32_t lowest[] = {0, 0, 0x80, 0x800, 0x10000};
  if (cp < lowest[n] || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF)) return 0;  // overlong, beyond, surrogate
  const bool invisible = cp <= 0x9F || (cp >= 0x200B && cp <= 0x200F) || (cp >= 0x202A && cp <= 0x202E) ||
                         (cp >= 0x2060 && cp <= 0x2069) || cp == 0xFEFF;
  return invisible ? 0 : n;
}

// A message's text with control characters and bytes that show nothing as
// \xNN (shown_path).
std::string without_controls(const std::string& s) {
  std::string out;
  for (size_t i = 0; i < s.size();) {
    const auto c = static_cast<unsigned char>(s[i]);
    if (c >= 0x20 && c < 0x7F) {
      out += s[i++];
      continue;
    }
    if (const size_t n = c >= 0x80 ? visible_utf8(s, i) : 0; n != 0) {
      out.append(s, i, n);
      i += n;
      continue;
    }
    char hex[8];
    std::snprintf(hex, sizeof hex, "\\x%02X", c);
    out += hex;
    ++i;
  }
  return out;
}

}  // namespace

std::string why_nul_in_name(const std::string& name) {
  const size_t nul = name.find('\0');
  if (nul == std::string::npos) return "";
  return "'" + shown_path(name.substr(0, nul)) + "' is followed by a NUL byte inside the name (character " +
         std::to_string(nul + 1) + "): the system would read the name only up to it";
}

std::string FrameNames::why_repeated(const std::string& name, long line, const std::string& path) {
  static const char* const kWhy = ": each row names its own image (a repeated frame would read as a standstill)";
  const auto [first, fresh] = line_of_.emplace(std::filesystem::path(name).lexically_normal().string(), line);
  // Names through shown_path, as every field of a table (was: an escape
  // sequence in a name went to the terminal).
  if (!fresh) return "filename '" + shown_path(name) + "' is also the frame of line " + std::to_string(first->second) + kWhy;
  // Another name for an earlier row's file (a symbolic or hard link) is the
  // same frame read twice (was: exit 0, the repeated frame read as a standstill).
  struct stat st {};
  if (path.empty() || ::stat(path.c_str(), &st) != 0 || !S_ISREG(st.st_mode)) return "";
  const auto [same, new_file] = file_of_.emplace(
      std::make_pair(static_cast<unsigned long long>(st.st_dev), static_cast<unsigned long long>(st.st_ino)),
      Seen{line, name, table_});
  if (new_file) return "";
  return "filename '" + shown_path(name) + "' is the same file as '" + shown_path(same->second.name) + "', the frame of line " +
         std::to_string(same->second.line) + (same->second.table != table_ ? " of " + shown_path(same->second.table) : "") +
         " (a link to it)" + kWhy;
}

void FrameNames::next_table(const std::string& table) {
  table_ = table;
  line_of_.clear();
}

std::string why_too_big_for_text(const std::string& path, const std::string& holds) {
  std::error_code e;
  const std::uintmax_t bytes = std::filesystem::file_size(path, e);
  if (e || bytes <= kMaxTextFileBytes) return "";
  return "the file is " + std::to_string(bytes) + " bytes: " + holds + " (at most " + std::to_string(kMaxTextFileBytes) +
         " bytes are read)";
}

CharDevice char_device_of(const std::string& path) {
  struct stat st {};
  CharDevice d;
  if (::stat(path.c_str(), &st) != 0 || !S_ISCHR(st.st_mode)) return d;
  d.major = major(st.st_rdev);
  d.minor = minor(st.st_rdev);
  const std::string node = "/sys/dev/char/" + std::to_string(d.major) + ":" + std::to_string(d.minor);
  std::error_code e1, e2;
  const std::filesystem::path device = std::filesystem::read_symlink(node, e1);
  const std::filesystem::path subsystem = std::filesystem::read_symlink(node + "/subsystem", e2);
  if (!e1) d.name = device.filename().string();
  if (!e2) d.subsystem = subsystem.filename().string();
  return d;
}

std::string why_not_a_device(const std::string& path, const std::string& what, const std::string& subsystem,
                             const std::string& name) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) return stat_failure(path, errno);
  if (S_ISCHR(st.st_mode)) {
    const CharDevice d = char_device_of(path);
    const bool other = (!subsystem.empty() && !d.subsystem.empty() && d.subsystem != subsystem) ||
                       (!name.empty() && !d.name.empty() && d.name != name);
    if (!other) return {};
    return "is the character device " + std::to_string(d.major) + ":" + std::to_string(d.minor) + " (" +
           d.subsystem + (d.subsystem.empty() || d.name.empty() ? "" : " ") + d.name + "), not a " + what;
  }
  if (S_ISREG(st.st_mode)) return "is a regular file, not a " + what;
  if (S_ISDIR(st.st_mode)) return "is a folder, not a " + what;
  return std::string("is ") + special_kind(st.st_mode) + ", not a " + what;
}

std::string why_not_a_file(const std::string& path, const std::string& what) {
  struct stat st {};
  if (path.empty()) return "an empty path, not a " + what;
  if (::stat(path.c_str(), &st) != 0) return stat_failure(path, errno);
  if (S_ISREG(st.st_mode)) return {};
  if (S_ISDIR(st.st_mode)) return "is a folder, not a " + what;
  return std::string("is ") + special_kind(st.st_mode) + ", not a " + what;
}

std::string why_not_a_folder(const std::string& path, const std::string& what) {
  struct stat st {};
  if (path.empty()) return "an empty path, not a " + what;
  if (::stat(path.c_str(), &st) != 0) return stat_failure(path, errno);
  if (S_ISDIR(st.st_mode)) return {};
  if (S_ISREG(st.st_mode)) return "is a file, not a " + what;
  return std::string("is ") + special_kind(st.st_mode) + ", not a " + what;
}

std::string why_dash_is_not_an_output(const std::string& what, const std::string& kind) {
  return "'-' stands for standard output, where no " + what + " is written: give a " + kind + " name (./- for a " +
         kind + " of that name)";
}

std::string why_inner_mav0(const std::string& out) {
  std::string p = out;
  while (p.size() > 1 && p.back() == '/') p.pop_back();
  const size_t slash = p.find_last_of('/');
  if (p.substr(slash == std::string::npos ? 0 : slash + 1) != "mav0") return "";
  const std::string parent = slash == std::string::npos ? "." : (slash == 0 ? "/" : p.substr(0, slash));
  return p + " is a recording's mav0 folder (the recording is written into a mav0 folder inside the one given: this "
             "would make " + p + "/mav0): give " + parent;
}

std::string written_path(const std::string& path) {
  const std::string to = dangling_link_target(path);
  std::error_code ec;
  const std::filesystem::path p = std::filesystem::weakly_canonical(to.empty() ? path : to, ec);
  return ec ? std::string() : p.string();
}

std::string why_not_writable(const std::string& path, const std::string& what) {
  struct stat st {};
  if (path.empty()) return "an empty path, not a " + what;
  // '-' is standard output where an output can go there (run -o -, --plot -);
  // elsewhere a file named '-' was made, unsaid.
  if (path == "-") return why_dash_is_not_an_output(what);
  if (::stat(path.c_str(), &st) == 0) return S_ISDIR(st.st_mode) ? "is a folder, not a " + what : std::string();
  if (errno != ENOENT) return stat_failure(path, errno);
  // A dangling symbolic link is written through: its target must be creatable
  // (was: passed, then 'cannot create the CSV: No such file or directory', or
  // for an output folder 'cannot create folder: File exists').
  if (const std::string to = dangling_link_target(path); !to.empty()) {
    const std::string why = why_not_writable(to, what);
    return why.empty() ? why : "is a symbolic link to " + shown_path(to) + ", which " + why;
  }
  const size_t slash = path.find_last_of('/');
  const std::string folder = slash == std::string::npos ? "." : slash == 0 ? "/" : path.substr(0, slash);
  if (const std::string why = why_not_a_folder(folder); !why.empty())
    return "cannot be created: its folder " + shown_path(folder) + " " + why;
  if (::access(folder.c_str(), W_OK | X_OK) != 0)
    return "cannot be created: no permission to write in its folder " + shown_path(folder);
  return {};
}

std::string why_not_a_writable_folder(const std::string& path, const std::string& what) {
  if (path.empty()) return "an empty path, not a " + what;
  if (path_present(path)) {
    if (const std::string why = why_not_a_folder(path, what); !why.empty()) return why;
    return ::access(path.c_str(), W_OK | X_OK) == 0 ? std::string() : "no permission to write in it";
  }
  // The folders missing on the way are made under the nearest part that is
  // there (was: 'filesystem error: cannot create directories: File exists
  // [lnk/sub/results]' for a dangling link lnk, or 'Permission denied').
  std::filesystem::path at = std::filesystem::path(path).parent_path();
  while (!at.empty() && !path_present(at.string()) && at != at.parent_path()) at = at.parent_path();
  const std::string folder = at.empty() ? "." : at.string();
  if (const std::string why = why_not_a_folder(folder); !why.empty())
    return "cannot be created: its folder " + shown_path(folder) + " " + why;
  if (::access(folder.c_str(), W_OK | X_OK) != 0)
    return "cannot be created: no permission to write in its folder " + shown_path(folder);
  return {};
}

std::string temporary_name_for(const std::string& path) {
  static std::atomic<unsigned> given{0};
  const std::string suffix = ".tmp" + std::to_string(::getpid()) + "-" + std::to_string(given++);
  const size_t slash = path.find_last_of('/');
  const size_t at = slash == std::string::npos ? 0 : slash + 1;
  std::string name = path.substr(at);
  if (name.size() + suffix.size() > NAME_MAX) name.resize(NAME_MAX - suffix.size());
  return path.substr(0, at) + name + suffix;
}

std::string left_by_a_stopped_write(const std::string& path) {
  const size_t slash = path.find_last_of('/');
  const std::string folder = slash == std::string::npos ? "." : path.substr(0, slash + 1);
  const std::string name = path.substr(slash == std::string::npos ? 0 : slash + 1);
  std::error_code ec;
  for (std::filesystem::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string other = it->path().filename().string();
    // NAME.tmpPID-N (a long NAME cut to make room is not looked for).
    if (other.size() <= name.size() + 4 || other.compare(0, name.size(), name) != 0 ||
        other.compare(name.size(), 4, ".tmp") != 0)
      continue;
    const std::string tail = other.substr(name.size() + 4);
    const size_t dash = tail.find('-');
    const auto digits = [](const std::string& t) {
      return !t.empty() && std::all_of(t.begin(), t.end(), [](char c) { return c >= '0' && c <= '9'; });
    };
    if (dash == std::string::npos || !digits(tail.substr(0, dash)) || !digits(tail.substr(dash + 1))) continue;
    return " (" + shown_path(other) +
           " lies beside it: the file of a write stopped before its end, as a render interrupted by Ctrl-C leaves; "
           "write it again)";
  }
  return {};
}

std::FILE* open_for_writing(const std::string& path, const char* mode, std::string& why) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0 || !S_ISFIFO(st.st_mode)) {
    std::FILE* f = std::fopen(path.c_str(), mode);
    if (!f) why = std::strerror(errno);
    return f;
  }
  // A FIFO opened for writing blocks until a process opens it for reading:
  // forever when none does. Opened without blocking, it fails (ENXIO) while
  // there is no reader.
  const auto end = std::chrono::steady_clock::now() + std::chrono::milliseconds(kFifoReaderWaitMs);
  for (;;) {
    const int fd = ::open(path.c_str(), O_WRONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd >= 0) {
      const int flags = ::fcntl(fd, F_GETFL);
      std::FILE* f = flags == -1 || ::fcntl(fd, F_SETFL, flags & ~O_NONBLOCK) == -1 ? nullptr : ::fdopen(fd, mode);
      if (!f) {
        why = std::strerror(errno);
        ::close(fd);
      }
      return f;
    }
    if (errno != ENXIO) {
      why = std::strerror(errno);
      return nullptr;
    }
    if (std::chrono::steady_clock::now() >= end) {
      why = "is a FIFO (named pipe) that no process reads (none came within " +
            std::to_string(kFifoReaderWaitMs / 1000) + " s): start its reader first, or write to a file";
      return nullptr;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
}

std::string standard_output_file() {
  struct stat out {}, named {};
  if (::fstat(STDOUT_FILENO, &out) != 0 || !S_ISREG(out.st_mode)) return "";
  std::error_code ec;
  const std::string path = std::filesystem::read_symlink("/proc/self/fd/1", ec).string();
  // The name the system gives is the file's only while it is that file (a
  // removed one reads 'PATH (deleted)').
  if (ec || ::stat(path.c_str(), &named) != 0 || named.st_dev != out.st_dev || named.st_ino != out.st_ino) return "";
  return path;
}

bool path_present(const std::string& path) {
  struct stat st {};
  // lstat: a dangling symbolic link is something there (a ground truth that
  // is a link to a moved file was taken for no ground truth, exit 0).
  if (::lstat(path.c_str(), &st) == 0) return true;
  return errno != ENOENT;
}

bool lies_inside(const std::string& path, const std::string& folder) {
  std::error_code ec;
  const std::filesystem::path f = std::filesystem::weakly_canonical(folder, ec),
                              p = std::filesystem::weakly_canonical(path, ec);
  return std::mismatch(f.begin(), f.end(), p.begin(), p.end()).first == f.end();
}

std::string shown_text(const std::string& text) { return without_controls(text); }

std::string shown_path(const std::string& path) {
  constexpr size_t kShown = 200, kEnds = 60;
  if (path.size() <= kShown) return without_controls(path);
  return without_controls(path.substr(0, kEnds)) + "..." + without_controls(path.substr(path.size() - kEnds)) + " (" +
         std::to_string(path.size()) + " characters)";
}

}  // namespace lumavel::host
