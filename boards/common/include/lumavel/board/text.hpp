// Fixed-buffer text for firmware console lines (no printf, no heap).
#pragma once
#include <cstddef>
#include <cstdint>

namespace lumavel::board {

template <size_t N>
class Text {
 public:
  Text& operator<<(const char* s) {
    while (*s != '\0') put(*s++);
    return *this;
  }
  Text& operator<<(uint64_t v) {
    char digits[20];
    int n = 0;
    do {
      digits[n++] = static_cast<char>('0' + v % 10);
      v /= 10;
    } while (v != 0);
    while (n > 0) put(digits[--n]);
    return *this;
  }
  Text& operator<<(uint32_t v) { return *this << uint64_t{v}; }
  Text& operator<<(int32_t v) {
    if (v < 0) {
      put('-');
      return *this << (uint64_t{0} - static_cast<uint64_t>(int64_t{v}));
    }
    return *this << static_cast<uint64_t>(v);
  }
  const char* c_str() {
    buf_[len_] = '\0';
    return buf_;
  }
  void clear() { len_ = 0; }

 private:
  void put(char c) {
    if (len_ < N - 1) buf_[len_++] = c;
  }
  char buf_[N]{};
  size_t len_ = 0;
};

}  // namespace lumavel::board
