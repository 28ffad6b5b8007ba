// The rules for text read by the tools, shared by the readers of recordings,
// slider datasets and configuration files so that each rule is said once.
#pragma once
#include <cstddef>
#include <string>

namespace lumavel::host {

// TEXT read whole as a decimal number: strtod's syntax ("1.5", "-2e-3",
// "inf", "nan") without its hexadecimal form ("0x1p-4" is 0.0625 to strtod;
// no file these tools read means one, and a damaged field must not pass as
// one). `value` is set when `problem` is kNone or kNotFinite.
struct DecimalText {
  enum class Problem {
    kNone,
    kEmpty,
    kNulByte,      // a NUL byte inside (strtod would stop there): at `nul_at`
    kNotANumber,   // not the whole of the text is a number
    kHexadecimal,  // a number, but C's hexadecimal form
    kOverflow,     // a number beyond the largest double (about 1.8e308)
    kNotFinite,    // "inf" or "nan" as written
  };
  Problem problem = Problem::kNone;
  double value = 0;
  size_t nul_at = 0;
  bool underflow = false;  // kNone, but smaller than the smallest double (read as 0 or subnormal)
};
DecimalText read_decimal(const std::string& text);

}  // namespace lumavel::host
