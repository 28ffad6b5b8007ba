#include "lumavel/host/line_ends.hpp"

namespace lumavel::host {

std::string why_cr_inside_line(const std::string& line) {
  const size_t cr = line.find('\r');
  if (cr == std::string::npos || line.find_first_not_of("\r \t", cr) == std::string::npos) return "";
  return "a carriage return (CR) inside the line, at character " + std::to_string(cr + 1) +
         ": lines must end with LF or CR LF (CR-only line ends?)";
}

std::string why_wide_text(const std::string& first_line) {
  const std::string& s = first_line;
  const auto starts = [&](const char* bytes, size_t n) { return s.size() >= n && s.compare(0, n, bytes, n) == 0; };
  std::string kind;
  if (starts("\xFF\xFE\0\0", 4)) kind = "UTF-32 text (little-endian: it starts with the byte-order mark FF FE 00 00)";
  else if (starts("\0\0\xFE\xFF", 4)) kind = "UTF-32 text (big-endian: it starts with the byte-order mark 00 00 FE FF)";
  else if (starts("\xFF\xFE", 2)) kind = "UTF-16 text (little-endian: it starts with the byte-order mark FF FE)";
  else if (starts("\xFE\xFF", 2)) kind = "UTF-16 text (big-endian: it starts with the byte-order mark FE FF)";
  else if (s.size() >= 4 && s[0] != '\0' && s[1] == '\0' && s[2] != '\0' && s[3] == '\0')
    kind = "UTF-16 text (little-endian, without a byte-order mark: a NUL byte after each character)";
  else if (s.size() >= 4 && s[0] == '\0' && s[1] != '\0' && s[2] == '\0' && s[3] != '\0')
    kind = "UTF-16 text (big-endian, without a byte-order mark: a NUL byte before each character)";
  if (kind.empty()) return "";
  return "the file is " + kind + ": the tools read ASCII or UTF-8 text (save it as UTF-8)";
}

}  // namespace lumavel::host
