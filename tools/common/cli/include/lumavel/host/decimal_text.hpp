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
// The words for a number that `underflow` flags, for messages: what it is
// read as (0, or a subnormal) is not the value written, and a rule said of
// that value ('= 0 must be positive') is not the value's fault.
extern const char* const kNearerZeroThanAnyNumber;  // "nearer 0 than the smallest number (about 2.2e-308)"

// TEXT read whole as a whole number: decimal digits with an optional sign,
// nothing else (no spaces). A leading zero is refused: "040" is 32 to C's
// base-0 readers (CLI11 converts its integer options so: `--width 040` ran
// at 32 columns after the range check had read 40), 40 to others; which one
// was meant is not for the tools to guess. "0" itself is a number.
struct WholeText {
  enum class Problem {
    kNone,
    kNotAWholeNumber,  // empty, or not only digits after the sign
    kLeadingZero,      // digits, but starting with 0 ("040", "-07", "00")
    kOverflow,         // digits beyond 64 bits
  };
  Problem problem = Problem::kNone;
  long long value = 0;  // set when problem is kNone
};
WholeText read_whole(const std::string& text);
// The rule broken, in words ("" for kNone): for messages.
const char* whole_text_rule(WholeText::Problem p);

}  // namespace lumavel::host
