// Where a stream board's bytes come from and go to: a host file, or a file
// opened through semihosting. The only thing that differs between the QEMU
// firmware and the host build of the same app.
#pragma once
#include <cstddef>
#include <cstdint>

namespace lumavel::stream {

class ByteSource {
 public:
  // Reads up to len bytes; returns how many (fewer only at end of file or on error).
  virtual size_t read(uint8_t* buf, size_t len) = 0;

 protected:
  ~ByteSource() = default;
};

class ByteSink {
 public:
  virtual bool write(const uint8_t* buf, size_t len) = 0;

 protected:
  ~ByteSink() = default;
};

}  // namespace lumavel::stream
