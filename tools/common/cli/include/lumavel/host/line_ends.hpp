// What ends a line of the text files the tools read (recording tables,
// slider datasets, configuration files, sensor.yaml and scenarios): LF or CR
// LF, and what they are written in: ASCII or UTF-8. One rule for all.
#pragma once
#include <string>

namespace lumavel::host {

// "" when `line` (its LF removed) holds no carriage return before more text
// (a CR LF's CR, with spaces at most after it, is fine); otherwise why it is
// refused: a file of CR-only line ends reads as one long line, and the
// reason says so.
std::string why_cr_inside_line(const std::string& line);

// "" unless `first_line` (a file's first line, as read up to its LF) is the
// start of UTF-16 or UTF-32 text (a byte-order mark FF FE, FE FF, FF FE 00 00
// or 00 00 FE FF; or, with none, a NUL byte beside each of its first two
// characters): the tools read ASCII or UTF-8, and such a file (Notepad's
// "Unicode", Windows PowerShell's redirections) was refused for what its
// bytes then look like ("missing header line", "a NUL byte at character 4",
// a CR inside the line). Otherwise the reason, e.g. "the file is UTF-16
// text (little-endian: it starts with the byte-order mark FF FE): the tools
// read ASCII or UTF-8 text (save it as UTF-8)".
std::string why_wide_text(const std::string& first_line);

}  // namespace lumavel::host
