#include "lumavel/host/decimal_text.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>

namespace lumavel::host {

const char* const kNearerZeroThanAnyNumber = "nearer 0 than the smallest number (about 2.2e-308)";

DecimalText read_decimal(const std::string& text) {
  DecimalText d;
  using P = DecimalText::Problem;
  if (text.empty()) {
    d.problem = P::kEmpty;
    return d;
  }
  if (const size_t nul = text.find('\0'); nul != std::string::npos) {
    d.problem = P::kNulByte;
    d.nul_at = nul;
    return d;
  }
  char* end = nullptr;
  errno = 0;
  d.value = std::strtod(text.c_str(), &end);
  const bool range = errno == ERANGE;
  if (end == text.c_str() || end != text.c_str() + text.size()) {
    d.problem = P::kNotANumber;
    return d;
  }
  // strtod's hexadecimal form: optional spaces and sign, then 0x or 0X.
  size_t at = text.find_first_not_of(" \t\n\v\f\r");
  if (at != std::string::npos && (text[at] == '+' || text[at] == '-')) ++at;
  if (at + 1 < text.size() && text[at] == '0' && (text[at + 1] == 'x' || text[at + 1] == 'X')) {
    d.problem = P::kHexadecimal;
    return d;
  }
  if (std::isinf(d.value) && range) d.problem = P::kOverflow;
  else if (!std::isfinite(d.value)) d.problem = P::kNotFinite;
  else d.underflow = range;
  return d;
}

WholeText read_whole(const std::string& text) {
  WholeText w;
  using P = WholeText::Problem;
  const size_t digits = text.empty() || (text[0] != '+' && text[0] != '-') ? 0 : 1;
  if (digits == text.size() || text.find_first_not_of("0123456789", digits) != std::string::npos) {
    w.problem = P::kNotAWholeNumber;
    return w;
  }
  if (text[digits] == '0' && text.size() > digits + 1) {
    w.problem = P::kLeadingZero;
    return w;
  }
  char* end = nullptr;
  errno = 0;
  w.value = std::strtoll(text.c_str(), &end, 10);
  if (errno == ERANGE) {
    w.problem = P::kOverflow;
    w.value = 0;
  }
  return w;
}

const char* whole_text_rule(WholeText::Problem p) {
  switch (p) {
    case WholeText::Problem::kNone: return "";
    case WholeText::Problem::kNotAWholeNumber: return "not a whole number";
    case WholeText::Problem::kLeadingZero:
      return "a leading zero (octal to some readers, decimal to others): write the number without it";
    case WholeText::Problem::kOverflow: return "beyond 64 bits";
  }
  return "";
}

}  // namespace lumavel::host
