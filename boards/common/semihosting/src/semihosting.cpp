#include "lumavel/board/semihosting.hpp"

namespace lumavel::semihost {
namespace {

constexpr uint32_t kSysOpen = 0x01;
constexpr uint32_t kSysClose = 0x02;
constexpr uint32_t kSysWrite0 = 0x04;
constexpr uint32_t kSysWrite = 0x05;
constexpr uint32_t kSysRead = 0x06;
constexpr uint32_t kSysGetCmdline = 0x15;
constexpr uint32_t kSysExitExtended = 0x20;
constexpr uint32_t kApplicationExit = 0x20026;

int32_t call(uint32_t op, const void* args) { return lumavel_semihost_trap(op, args); }

size_t length(const char* s) {
  size_t n = 0;
  while (s[n] != '\0') ++n;
  return n;
}

}  // namespace

bool command_line(char* buf, size_t cap) {
  uint32_t args[2] = {reinterpret_cast<uint32_t>(buf), static_cast<uint32_t>(cap)};
  return call(kSysGetCmdline, args) == 0;
}

int open(const char* path, int mode) {
  const uint32_t args[3] = {reinterpret_cast<uint32_t>(path), static_cast<uint32_t>(mode),
                            static_cast<uint32_t>(length(path))};
  return call(kSysOpen, args);
}

void close(int handle) {
  const uint32_t args[1] = {static_cast<uint32_t>(handle)};
  call(kSysClose, args);
}

size_t read(int handle, uint8_t* buf, size_t len) {
  const uint32_t args[3] = {static_cast<uint32_t>(handle), reinterpret_cast<uint32_t>(buf),
                            static_cast<uint32_t>(len)};
  const int32_t not_read = call(kSysRead, args);
  return not_read < 0 || static_cast<size_t>(not_read) > len ? 0 : len - static_cast<size_t>(not_read);
}

size_t write(int handle, const uint8_t* buf, size_t len) {
  const uint32_t args[3] = {static_cast<uint32_t>(handle), reinterpret_cast<uint32_t>(buf),
                            static_cast<uint32_t>(len)};
  const int32_t not_written = call(kSysWrite, args);
  return not_written < 0 || static_cast<size_t>(not_written) > len ? 0 : len - static_cast<size_t>(not_written);
}

void write_text(const char* text) { call(kSysWrite0, text); }

void exit(int code) {
  const uint32_t args[2] = {kApplicationExit, static_cast<uint32_t>(code)};
  call(kSysExitExtended, args);
  for (;;) {
  }
}

bool FileSink::write(const uint8_t* buf, size_t len) {
  for (size_t i = 0; i < len; ++i) {
    if (used_ == sizeof buf_ && !flush()) return false;
    buf_[used_++] = buf[i];
  }
  return true;
}

bool FileSink::flush() {
  const bool ok = semihost::write(h_, buf_, used_) == used_;
  used_ = 0;
  return ok;
}

int split_words(char* line, char** words, int max) {
  int n = 0;
  for (char* p = line; *p != '\0' && n < max;) {
    while (*p == ' ') *p++ = '\0';
    if (*p == '\0') break;
    words[n++] = p;
    while (*p != '\0' && *p != ' ') ++p;
  }
  return n;
}

}  // namespace lumavel::semihost
