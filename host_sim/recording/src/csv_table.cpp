#include "lumavel/host/csv_table.hpp"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <limits>
#include <new>

#include "lumavel/host/decimal_text.hpp"
#include "lumavel/host/line_ends.hpp"
#include "lumavel/host/path_check.hpp"
#include "lumavel/host/recording_error.hpp"

namespace lumavel::host {
namespace {

std::string trim(const std::string& s) {
  size_t b = 0, e = s.size();
  while (b < e && (s[b] == ' ' || s[b] == '\t' || s[b] == '\r')) ++b;
  while (e > b && (s[e - 1] == ' ' || s[e - 1] == '\t' || s[e - 1] == '\r')) --e;
  return s.substr(b, e - b);
}

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out;
  size_t start = 0;
  for (;;) {
    const size_t comma = line.find(',', start);
    out.push_back(trim(line.substr(start, comma == std::string::npos ? std::string::npos : comma - start)));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return out;
}

// A field as messages show it: a 10 MB field is shortened like a long path.
std::string shown(const std::string& field) { return shown_path(field); }

std::string join(const std::vector<std::string>& v) {
  std::string s;
  for (size_t i = 0; i < v.size(); ++i) s += (i ? "," : "") + v[i];
  return s;
}

}  // namespace

double parse_finite(const std::string& text, const std::string& path, long line, const std::string& column) {
  const DecimalText d = read_decimal(text);
  const std::string col = "column '" + column + "'";
  switch (d.problem) {
    case DecimalText::Problem::kNone: return d.value;
    case DecimalText::Problem::kEmpty: throw recording_error_at(path, line, col + " is empty");
    case DecimalText::Problem::kNulByte:  // strtod stops at it: "9<NUL>0.0092" would be read as 9
      throw recording_error_at(path, line, col + ": '" + text.substr(0, d.nul_at) +
                                               "' is followed by a NUL byte inside the number (character " +
                                               std::to_string(d.nul_at + 1) + "): not a number");
    case DecimalText::Problem::kNotANumber:
      throw recording_error_at(path, line, col + ": '" + shown(text) + "' is not a number");
    case DecimalText::Problem::kHexadecimal:  // no writer of these tables means one ("0x10" is 16 to strtod)
      throw recording_error_at(path, line, col + ": '" + shown(text) +
                                               "' is a hexadecimal number: only decimal numbers are read");
    case DecimalText::Problem::kOverflow:
      throw recording_error_at(path, line, col + ": value '" + shown(text) +
                                               "' is beyond the largest number (about 1.8e308)");
    case DecimalText::Problem::kNotFinite: break;
  }
  throw recording_error_at(path, line, col + ": value '" + shown(text) + "' is not finite");
}

std::string format_double(double v) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::general);
  return std::string(buf, r.ptr);
}

namespace {

// Lines longer than this are not rows of these tables (a timestamp and a few
// numbers or a file name): a binary or damaged file, refused at once rather
// than read whole into memory looking for its end.
constexpr std::streamsize kMaxLineChars = std::streamsize{1} << 24;

}  // namespace

bool next_table_line(std::istream& in, std::vector<char>& buf, std::string& out, const std::string& path, long line) {
  if (buf.size() < 2) buf.resize(4096);
  out.clear();
  for (;;) {
    in.getline(buf.data(), static_cast<std::streamsize>(buf.size()));
    if (in.bad()) throw recording_error_in(path, "read error");
    const std::streamsize got = in.gcount();
    const bool full = in.fail() && !in.eof() && got == static_cast<std::streamsize>(buf.size()) - 1;
    if (in.fail() && !full && got == 0 && out.empty()) return false;  // the end of the file
    const std::streamsize n = full || in.eof() ? got : got - 1;  // without the '\n' read
    if (n > 0) out.append(buf.data(), static_cast<size_t>(n));
    if (static_cast<std::streamsize>(out.size()) > kMaxLineChars)
      throw recording_error_at(path, line, "line is longer than " + std::to_string(kMaxLineChars) +
                                               " characters: not a row of this table (a binary or damaged file?)");
    if (!full) {
      if (in.fail()) in.clear(std::ios::eofbit);  // the last line, read: the next call ends
      // A UTF-16 or UTF-32 file is said as such at its first line (was:
      // 'missing header line', or a CR inside it for CR LF ends).
      if (line == 1)
        if (const std::string why = why_wide_text(out); !why.empty()) throw recording_error_at(path, line, why);
      // CR LF ends a line; a CR with more after it is a file of CR-only
      // lines, which would otherwise read as one long header.
      if (const std::string why = why_cr_inside_line(out); !why.empty()) throw recording_error_at(path, line, why);
      return true;
    }
    in.clear();  // the chunk filled up before the line's end: more to come
  }
}

void for_each_csv_row(const std::string& path, const std::vector<std::string>& columns,
                      const std::function<void(const CsvRow&)>& on_row) {
  if (const std::string why = why_not_a_file(path); !why.empty())
    throw recording_error_in(path, why == "does not exist" ? why + left_by_a_stopped_write(path) : why);
  std::ifstream in(path);
  if (!in) throw recording_error_in(path, std::string("cannot open: ") + std::strerror(errno));
  std::string text;
  std::vector<char> buf(4096);
  if (!next_table_line(in, buf, text, path, 1)) throw recording_error_at(path, 1, "empty file: missing header line");
  if (text.rfind("\xEF\xBB\xBF", 0) == 0) text.erase(0, 3);  // UTF-8 byte order mark
  const std::vector<std::string> header = split(trim(text));
  if (header.empty() || header[0].empty() || header[0][0] != '#')
    throw recording_error_at(path, 1,
                             "missing header line: expected '#timestamp [ns]," + join(columns) + "'");
  if (header[0] != "#timestamp [ns]" && header[0] != "#timestamp")
    throw recording_error_at(path, 1, "first column is '" + shown(header[0]) + "', expected '#timestamp [ns]'");
  for (size_t i = 0; i < columns.size(); ++i) {
    if (i + 1 >= header.size())
      throw recording_error_at(path, 1, "missing column '" + columns[i] + "' in the header");
    if (header[i + 1] != columns[i])
      throw recording_error_at(path, 1,
                               "header column " + std::to_string(i + 1) + " is '" + shown(header[i + 1]) +
                                   "', expected '" + columns[i] + "'");
  }
  if (header.size() > columns.size() + 1)
    throw recording_error_at(path, 1, "unexpected extra column '" + shown(header[columns.size() + 1]) + "' in the header");

  CsvRow row;
  bool any = false;
  uint64_t prev_t = 0;
  long prev_line = 0;
  long line = 1;
  size_t rows_held = 0;
  while (next_table_line(in, buf, text, path, line + 1)) {
    ++line;
    const std::string t = trim(text);
    if (t.empty()) continue;  // blank lines (a trailing newline) carry nothing
    row.line = line;
    row.fields = split(t);
    if (row.fields.size() != columns.size() + 1) {
      // NUL bytes where rows should be are what a file a crash or a full disk
      // cut short is padded with (was: 'expected 7 columns, found 1' alone,
      // the cause unsaid).
      std::string nul;
      if (t.find('\0') != std::string::npos)
        nul = ": the line holds " + std::to_string(std::count(t.begin(), t.end(), '\0')) +
              " NUL bytes, the first at character " + std::to_string(text.find('\0') + 1) +
              " (no part of a table's text: a damaged file, as one a crash or a full disk left padded with them)";
      throw recording_error_at(path, line,
                               "expected " + std::to_string(columns.size() + 1) + " columns, found " +
                                   std::to_string(row.fields.size()) + nul);
    }
    const std::string& ts = row.fields[0];
    const auto r = std::from_chars(ts.data(), ts.data() + ts.size(), row.t_ns);
    // EuRoC timestamps are int64 nanoseconds; beyond that, differences of
    // two of them no longer fit the engines' signed intervals.
    constexpr uint64_t kMaxTimestamp = static_cast<uint64_t>(std::numeric_limits<int64_t>::max());
    const bool digits = !ts.empty() && r.ptr == ts.data() + ts.size();
    if (digits && (r.ec == std::errc::result_out_of_range || (r.ec == std::errc() && row.t_ns > kMaxTimestamp)))
      throw recording_error_at(path, line,
                               "timestamp " + shown(ts) + " is beyond " + std::to_string(kMaxTimestamp) +
                                   " ns, the largest the format's signed 64-bit nanoseconds hold");
    if (!ts.empty() && ts[0] == '-' && ts.find_first_not_of("0123456789", 1) == std::string::npos && ts.size() > 1)
      throw recording_error_at(path, line, "timestamp " + shown(ts) + " is negative: timestamps are nanoseconds, 0 or more");
    if (!digits || r.ec != std::errc())
      throw recording_error_at(path, line, "timestamp '" + shown(ts) + "' is not an integer number of nanoseconds");
    if (any && row.t_ns <= prev_t)
      throw recording_error_at(path, line,
                               "timestamp " + ts + " is not after the previous one (" + std::to_string(prev_t) +
                                   ", line " + std::to_string(prev_line) + ")");
    any = true;
    prev_t = row.t_ns;
    prev_line = line;
    row.fields.erase(row.fields.begin());
    // A table too large for the memory there is (millions of rows) is named
    // at its row (was: "error: std::bad_alloc", naming nothing).
    try {
      on_row(row);
    } catch (const std::bad_alloc&) {
      throw recording_error_at(path, line,
                               "out of memory holding the table's rows (" + std::to_string(rows_held) +
                                   " of them before this one): the table is larger than the memory there is");
    }
    ++rows_held;
  }
}

std::vector<CsvRow> read_csv_table(const std::string& path, const std::vector<std::string>& columns) {
  std::vector<CsvRow> rows;
  for_each_csv_row(path, columns, [&](const CsvRow& r) { rows.push_back(r); });
  return rows;
}

}  // namespace lumavel::host
