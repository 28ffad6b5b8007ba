// What ends a line of the text files the tools read (recording tables,
// slider datasets, configuration files): LF or CR LF. One rule for all.
#pragma once
#include <string>

namespace lumavel::host {

// "" when `line` (its LF removed) holds no carriage return before more text
// (a CR LF's CR, with spaces at most after it, is fine); otherwise why it is
// refused: a file of CR-only line ends reads as one long line, and the
// reason says so.
std::string why_cr_inside_line(const std::string& line);

}  // namespace lumavel::host
