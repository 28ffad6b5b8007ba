// What a --device path is, before hidapi sees it: Debian 12's
// libhidapi-hidraw frees and then uses its device in hid_open_path when the
// path is not a hidraw node (/dev/null, a regular file: SIGSEGV), so only a
// hidraw character device is ever handed to it.
#pragma once
#include <string>

namespace lumavel::read {

// Empty when `path` is a hidraw character device or does not exist (hidapi
// says so itself); otherwise what it is instead, for the message:
// "/dev/null is the character device 1:3 (mem), not a hidraw device".
std::string why_not_hidraw(const std::string& path);

}  // namespace lumavel::read
