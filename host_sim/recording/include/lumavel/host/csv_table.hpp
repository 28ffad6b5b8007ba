// Strict reader for the numeric data.csv files of a recording: checks the
// header, the column count, the numbers and the timestamp order, and reports
// any problem as "FILE:LINE: ..." (the header is line 1).
#pragma once
#include <cstdint>
#include <functional>
#include <istream>
#include <string>
#include <vector>

namespace lumavel::host {

struct CsvRow {
  long line = 0;            // 1-based line in the file
  uint64_t t_ns = 0;        // first column
  std::vector<std::string> fields;  // remaining columns, trimmed
};

// `columns` are the expected header names after the timestamp; the timestamp
// column may be spelled "#timestamp [ns]" or "#timestamp" (EuRoC uses both).
// Timestamps must be unsigned integers, strictly increasing.
std::vector<CsvRow> read_csv_table(const std::string& path, const std::vector<std::string>& columns);

// Same checks, one row at a time (the row object is reused): long gyro files
// are parsed without keeping every field as text.
void for_each_csv_row(const std::string& path, const std::vector<std::string>& columns,
                      const std::function<void(const CsvRow&)>& row);

// The next line of a text table `path` into `out`, its LF removed (a CR LF's
// CR stays, for the caller's trim); false at the end of the file. `line` is its number, for
// messages; `buf` is scratch, read a chunk at a time. A line longer than a
// row of a table could be (a binary or damaged file) or with a CR inside it
// (CR-only line ends) throws RecordingError "FILE:LINE: ...", before the
// whole of it is in memory.
bool next_table_line(std::istream& in, std::vector<char>& buf, std::string& out, const std::string& path, long line);

// Parses a finite number; throws "FILE:LINE: column NAME: ..." otherwise.
double parse_finite(const std::string& text, const std::string& path, long line, const std::string& column);

// Shortest text that reads back as the same double.
std::string format_double(double v);

}  // namespace lumavel::host
