// Semihosting (the Arm semihosting interface, which RISC-V adopted): file
// I/O and exit through the debugger, here QEMU with
// -semihosting-config enable=on,target=native. The operations are the same on
// every core; only the trap differs, and each board defines it:
//   Cortex-M: bkpt 0xAB (boards/qemu-mps2-an385/semihost_trap.cpp)
//   RISC-V:   slli x0,x0,0x1f; ebreak; srai x0,x0,7 (boards/qemu-riscv-virt/semihost_trap.cpp)
#pragma once
#include <cstddef>
#include <cstdint>

#include "lumavel/stream/byte_io.hpp"

// The board's trap: operation number and argument block in, result out.
extern "C" int32_t lumavel_semihost_trap(uint32_t op, const void* args);

namespace lumavel::semihost {

// Command line given to QEMU (-semihosting-config ...,arg=a,arg=b): NUL-terminated.
bool command_line(char* buf, size_t cap);
// Handle or -1. mode: 1 = "rb", 5 = "wb".
int open(const char* path, int mode);
void close(int handle);
// Bytes transferred.
size_t read(int handle, uint8_t* buf, size_t len);
size_t write(int handle, const uint8_t* buf, size_t len);
void write_text(const char* text);  // to QEMU's console
// Splits a command line in place at spaces; returns the word count (<= max).
int split_words(char* line, char** words, int max);
[[noreturn]] void exit(int code);   // SYS_EXIT_EXTENDED: 0..255 reach QEMU's exit status

constexpr int kModeReadBinary = 1;
constexpr int kModeWriteBinary = 5;

class FileSource final : public stream::ByteSource {
 public:
  explicit FileSource(int handle) : h_(handle) {}
  size_t read(uint8_t* buf, size_t len) override { return semihost::read(h_, buf, len); }

 private:
  int h_;
};

// Buffers small writes: each semihosting call is a trap into QEMU.
class FileSink final : public stream::ByteSink {
 public:
  explicit FileSink(int handle) : h_(handle) {}
  bool write(const uint8_t* buf, size_t len) override;
  bool flush();

 private:
  int h_;
  uint8_t buf_[512]{};
  size_t used_ = 0;
};

}  // namespace lumavel::semihost
