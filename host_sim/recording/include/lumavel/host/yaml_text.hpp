// The text of a YAML file line by line, for what yaml-cpp's single-document
// Load does not say (a second document after '---', text after a '...' end
// marker, CR-only line ends, NUL bytes): the sensor.yaml reader and the
// scenario loader scan for those in the text (yaml-cpp's LoadAll can loop on
// malformed input).
#pragma once
#include <algorithm>
#include <string>

#include "lumavel/host/line_ends.hpp"

namespace lumavel::host::yaml_text {

// `line` is the document marker `marker` ("---" or "..."), alone or followed
// by a blank.
inline bool is_marker(const std::string& line, const char* marker) {
  return line.rfind(marker, 0) == 0 && (line.size() == 3 || line[3] == ' ' || line[3] == '\r' || line[3] == '\t');
}

// `line` holds something other than blanks and a '#' comment.
inline bool has_content(const std::string& line) {
  const size_t first = line.find_first_not_of(" \t\r");
  return first != std::string::npos && line[first] != '#';
}

// f(number, line) for each line of `text`, numbered from 1.
template <class F>
void for_each_line(const std::string& text, F f) {
  long number = 0;
  for (size_t at = 0; at < text.size();) {
    const size_t end = std::min(text.find('\n', at), text.size());
    f(++number, text.substr(at, end - at));
    at = end + 1;
  }
}

// Where `text` stops being one YAML document (Load reads the first and drops
// the rest, silently): a '---' after some content, or content after a '...'
// end marker. line 0: one document.
struct NotOneDocument {
  long line;
  std::string why;  // "a second YAML document (after '---')", "text after the end of the document (...)"
};
inline NotOneDocument why_not_one_document(const std::string& text) {
  NotOneDocument out{0, ""};
  bool content = false;
  long ended_at = 0;  // the line of a '...' after content
  for_each_line(text, [&](long n, const std::string& l) {
    if (out.line != 0) return;
    if (is_marker(l, "---")) {
      if (content) out = {n, "a second YAML document (after '---')"};
    } else if (is_marker(l, "...")) {
      if (content && ended_at == 0) ended_at = n;
    } else if (!content && ended_at == 0 && !l.empty() && l[0] == '%') {
      // A directive ('%YAML 1.2', '%TAG ...') before the document's '---'
      // is no content of it: '%YAML 1.2' then '---', one document as YAML
      // writers head it, was refused as 'a second YAML document'.
    } else if (has_content(l)) {
      if (ended_at != 0)
        out = {n, "text after the end of the document ('...' at line " + std::to_string(ended_at) + ")"};
      content = true;
    }
  });
  return out;
}

// What a file that loads as no document at all holds, for its refusal:
// "empty file" (nothing, or blanks alone), "no key: the file holds only
// comments" (and blank lines, document markers or directives), or "no key:
// line N is a null value" ('~' or 'null' alone). A file of comments alone
// was said to be an empty file, which it is not.
inline std::string why_null_document(const std::string& text) {
  long comment = 0, value = 0;
  for_each_line(text, [&](long n, const std::string& l) {
    const size_t first = l.find_first_not_of(" \t\r");
    if (first == std::string::npos) return;
    if (l[first] == '#' || is_marker(l, "---") || is_marker(l, "...") || l[0] == '%') {
      if (comment == 0) comment = n;
    } else if (value == 0) {
      value = n;
    }
  });
  if (value != 0) return "no key: line " + std::to_string(value) + " is a null value";
  if (comment != 0) return "no key: the file holds only comments";
  return "empty file";
}

// The first line that yaml-cpp would misread, and why: a first line of
// UTF-16 or UTF-32 text (why_wide_text's reason), a carriage return
// before more text (why_cr_inside_line's reason; yaml-cpp ends lines at LF
// and CR LF only, so a file of CR-only line ends is one long line to it, read
// as a comment, "empty file", when it starts with '#'), or a NUL byte (taken
// for an escape: "unknown escape character: j", at the line after).
struct BadLine {
  long line;  // 0: none
  std::string why;
};
inline BadLine why_bad_line(const std::string& text) {
  BadLine out{0, ""};
  for_each_line(text, [&](long n, const std::string& l) {
    if (out.line != 0) return;
    if (std::string wide = n == 1 ? why_wide_text(l) : ""; !wide.empty()) out = {n, wide};
    else if (std::string why = why_cr_inside_line(l); !why.empty()) out = {n, why};
    else if (const size_t nul = l.find('\0'); nul != std::string::npos)
      out = {n, "a NUL byte at character " + std::to_string(nul + 1) + ": a YAML file is text (a binary or damaged file?)"};
  });
  return out;
}

// What a syntax error at `line` adds when that line is indented with a tab
// (yaml-cpp says "illegal map value" or the like, not why): "" otherwise.
inline std::string tab_indent_note(const std::string& text, long line) {
  std::string note;
  for_each_line(text, [&](long n, const std::string& l) {
    if (n != line) return;
    const size_t first = l.find_first_not_of(" \t");
    if (l.find('\t') < std::min(first, l.size()))
      note = "; this line is indented with a tab, and YAML indents with spaces only";
  });
  return note;
}

}  // namespace lumavel::host::yaml_text
