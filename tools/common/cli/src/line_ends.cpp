#include "lumavel/host/line_ends.hpp"

namespace lumavel::host {

std::string why_cr_inside_line(const std::string& line) {
  const size_t cr = line.find('\r');
  if (cr == std::string::npos || line.find_first_not_of("\r \t", cr) == std::string::npos) return "";
  return "a carriage return (CR) inside the line, at character " + std::to_string(cr + 1) +
         ": lines must end with LF or CR LF (CR-only line ends?)";
}

}  // namespace lumavel::host
