#include "lumavel/host/cli.hpp"

#include "lumavel/host/path_check.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <memory>
#include <sstream>
#include <stdexcept>

#include "lumavel/host/decimal_text.hpp"

namespace lumavel::cli {
namespace {

// CLI11's help with the usage line first (then what the command does, its
// arguments, options, subcommands and the footer: the exit status).
class UsageFirst : public CLI::Formatter {
 public:
  UsageFirst() { column_width(30); }
  std::string make_help(const CLI::App* app, std::string name, CLI::AppFormatMode mode) const override {
    if (mode == CLI::AppFormatMode::Sub) return make_expanded(app);
    std::stringstream out;
    out << make_usage(app, name) << "\n";
    const std::string desc = make_description(app);
    if (!desc.empty()) out << desc;
    out << make_positionals(app) << make_groups(app, mode) << make_subcommands(app, mode);
    out << '\n' << make_footer(app);
    return out.str();
  }
  // In a list of commands, only the first paragraph of each description (its summary).
  std::string make_subcommand(const CLI::App* sub) const override {
    const std::string d = sub->get_description();
    std::stringstream out;
    CLI::detail::format_help(out, sub->get_display_name(true), d.substr(0, d.find("\n\n")), column_width_);
    return out.str();
  }
};

std::string in_quotes(const std::string& s) { return "'" + s + "'"; }

// Whole numbers as the files' (decimal_text.hpp): "040" is refused, not 40
// here and 32 to CLI11, which converts integer options in base 0.
bool parse_long(const std::string& s, long long& out) {
  const host::WholeText w = host::read_whole(s);
  out = w.value;
  return w.problem == host::WholeText::Problem::kNone;
}

bool has_leading_zero(const std::string& s) {
  return host::read_whole(s).problem == host::WholeText::Problem::kLeadingZero;
}

// What a message adds when a leading zero is what is wrong.
std::string leading_zero_note(bool zero) { return zero ? ", written without a leading zero (octal to some readers)" : ""; }

// What a message adds when a space is what is wrong: the options' numbers
// are a number's characters alone, a sign included ('+40' is 40 to every
// reader of these tools: decimal_text.hpp), but a space is no part of one
// (' 20', '20 ' were refused as 'not a whole number' with no word of the
// space, which the quotes alone show; a value built by a script with a stray
// space or two values in one argument, '20 15', is a mistake to show).
std::string space_note(const std::string& s) {
  const bool space = std::any_of(s.begin(), s.end(), [](char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; });
  return space ? ", written without spaces (a space is no part of a number)" : "";
}

// Decimal only, as the files' numbers (decimal_text.hpp): '--baseline 0x1p-5'
// is refused, not 0.03125. A number nearer 0 than any double is refused too,
// as a file's is (a77d867): '--exposure 1e-400' rendered with exposure 0,
// exit 0, and '--max-shift 1e-400' was told 'must be a number in (0, 20]',
// a rule the number meets (underflow_note says why).
bool parse_double(const std::string& s, double& out) {
  if (s.empty() || std::isspace(static_cast<unsigned char>(s[0]))) return false;
  const host::DecimalText d = host::read_decimal(s);
  out = d.value;
  return d.problem == host::DecimalText::Problem::kNone && !d.underflow;
}

// What a message adds when the number is nearer 0 than any double.
std::string underflow_note(const std::string& s) {
  const host::DecimalText d = host::read_decimal(s);
  return d.problem == host::DecimalText::Problem::kNone && d.underflow
             ? std::string(", which is ") + host::kNearerZeroThanAnyNumber
             : std::string();
}

}  // namespace

const char* const kExitStatusHelp = "Exit status: 0 done, 1 bad input or failure (the message names the file\n"
                                    "and the line or frame), 2 usage error.";

Tool::Tool(const std::string& name, const std::string& description, const std::string& version,
           const std::string& exit_status)
    : app_(description, name), exit_status_(exit_status) {
  app_.formatter(std::make_shared<UsageFirst>());
  app_.set_version_flag("--version", name + " " + version, "print the version and exit");
  app_.set_help_flag("-h,--help", "print this help and exit");
  app_.footer(exit_status_);
  app_.require_subcommand(1);
  app_.option_defaults()->always_capture_default(false);
}

CLI::App* Tool::command(CLI::App& parent, const std::string& name, const std::string& description, Action action) {
  CLI::App* sub = parent.add_subcommand(name, description);
  sub->set_help_flag("-h,--help", "print this help and exit");
  sub->footer(exit_status_);
  if (action) actions_.emplace_back(sub, std::move(action));
  else sub->require_subcommand(1);
  return sub;
}

CLI::App* Tool::command(const std::string& name, const std::string& description, Action action) {
  return command(app_, name, description, std::move(action));
}

std::string Tool::path_of(const CLI::App* sub) const {
  std::string path;
  for (const CLI::App* a = sub; a != nullptr; a = a->get_parent()) path = a->get_name() + (path.empty() ? "" : " ") + path;
  return path;
}

namespace {

// "" when all that was written to standard output went out; otherwise
// "standard output: write error: REASON" (the reason of the flush that
// failed; stdio keeps only a flag for a failure inside an earlier write).
std::string stdout_write_error() {
  std::cout.flush();
  errno = 0;
  const bool flushed = std::fflush(stdout) == 0;
  const int err = errno;
  if (flushed && std::cout && !std::ferror(stdout)) return "";
  return std::string("standard output: write error") + (!flushed && err != 0 ? ": " + std::string(std::strerror(err)) : "");
}

// A parse error's text line by line through shown_text: CLI11 and the
// validators put the arguments in as they were typed (was: 'lumavel-sim
// r<ESC>[2Jun', a name a glob expanded, cleared the terminal with "unknown
// command 'r[2Jun'"; an option's value likewise).
std::string shown_lines(const std::string& text) {
  std::string out;
  for (size_t at = 0; at <= text.size();) {
    const size_t end = std::min(text.find('\n', at), text.size());
    out += host::shown_text(text.substr(at, end - at));
    if (end < text.size()) out += '\n';
    at = end + 1;
  }
  return out;
}

// A standard stream closed when the tool starts ('lumavel-sim run REC >&-'):
// the next file opened took its descriptor, and what was written to standard
// output went into that file (run's CSV into its own temporary copy, lost, exit
// 0, nothing said; a recording's file could have taken it as well). Each
// closed one is held by /dev/null opened read-only: a write to it fails
// (EBADF) and is said as standard output's write error, and no file the tool
// opens takes its number.
void hold_closed_standard_streams() {
  for (int fd = 0; fd <= 2; ++fd) {
    if (::fcntl(fd, F_GETFD) != -1 || errno != EBADF) continue;
    const int held = ::open("/dev/null", O_RDONLY);
    if (held >= 0 && held != fd) {
      ::dup2(held, fd);
      ::close(held);
    }
  }
}

}  // namespace

int Tool::run(int argc, const char* const* argv) {
  hold_closed_standard_streams();
  // The deepest command named so far: messages and help hints are its own.
  auto deepest = [this] {
    const CLI::App* a = &app_;
    for (;;) {
      const auto chosen = a->get_subcommands();
      if (chosen.empty()) return a;
      a = chosen.front();
    }
  };
  if (argc <= 1) {  // nothing asked: the overview, as a usage error
    std::cerr << app_.help();
    return kExitUsage;
  }
  try {
    app_.parse(argc, argv);
  } catch (const CLI::Success& e) {  // --help, --version
    const int status = app_.exit(e, std::cout, std::cerr) == 0 ? kExitOk : kExitUsage;
    // As a command's output: help lost on its way (a full disk, a closed
    // standard output) was exit 0, nothing said.
    std::cout.flush();
    if (const std::string why = stdout_write_error(); !why.empty()) {
      std::fprintf(stderr, "%s: error: %s\n", path_of(deepest()).c_str(), why.c_str());
      return kExitFailure;
    }
    return status;
  } catch (const CLI::ParseError& e) {
    const CLI::App* at = deepest();
    const std::string who = path_of(at);
    std::string what = e.what();
    if (what == "A subcommand is required") {
      const std::vector<std::string> rest = at->remaining();
      what = rest.empty() ? "a command is needed" : "unknown command '" + rest.front() + "'";
    }
    while (!what.empty() && std::isspace(static_cast<unsigned char>(what.back()))) what.pop_back();
    std::fprintf(stderr, "%s: %s\n(see %s --help)\n", who.c_str(), shown_lines(what).c_str(), who.c_str());
    return kExitUsage;
  }
  const CLI::App* chosen = deepest();
  for (const auto& [sub, action] : actions_) {
    if (sub != chosen) continue;
    try {
      const int status = action();
      // Output lost on its way (a full disk) is a failure, not exit 0.
      if (const std::string why = stdout_write_error(); !why.empty()) throw std::runtime_error(why);
      return status;
    } catch (const UsageError& e) {
      const std::string who = path_of(sub);
      std::fprintf(stderr, "%s: %s\n(see %s --help)\n", who.c_str(), e.what(), who.c_str());
      return kExitUsage;
    } catch (const std::exception& e) {
      std::fprintf(stderr, "%s: error: %s\n", path_of(sub).c_str(), e.what());
      return kExitFailure;
    }
  }
  std::fprintf(stderr, "%s: a command is needed\n(see %s --help)\n", path_of(chosen).c_str(), path_of(chosen).c_str());
  return kExitUsage;
}

int run_command_alone(const std::string& tool_name, const std::function<void(Tool&)>& add, int argc,
                      char** argv) {
  Tool tool(tool_name, "", "");
  add(tool);
  std::vector<const char*> args{tool_name.c_str()};
  for (int i = 0; i < argc; ++i) args.push_back(argv[i]);
  return tool.run(static_cast<int>(args.size()), args.data());
}

CLI::Validator whole_number_in(long long lo, long long hi, const std::string& note) {
  return CLI::Validator(
      [lo, hi, note](std::string& s) -> std::string {
        long long v = 0;
        if (!parse_long(s, v) || v < lo || v > hi)
          return "must be a whole number in " + std::to_string(lo) + ".." + std::to_string(hi) + note +
                 leading_zero_note(has_leading_zero(s)) + space_note(s) + ", not " + in_quotes(s);
        return {};
      },
      "");
}

CLI::Validator number_in(double lo, double hi) {
  return CLI::Validator(
      [lo, hi](std::string& s) -> std::string {
        double v = 0;
        if (!parse_double(s, v) || v < lo || v > hi)
          return "must be a number in [" + number_text(lo) + ", " + number_text(hi) + "]" + space_note(s) + ", not " +
                 in_quotes(s) + underflow_note(s);
        return {};
      },
      "");
}

CLI::Validator positive_number_up_to(double hi) {
  return CLI::Validator(
      [hi](std::string& s) -> std::string {
        double v = 0;
        if (!parse_double(s, v) || !(v > 0) || v > hi)
          return "must be a number in (0, " + number_text(hi) + "]" + space_note(s) + ", not " + in_quotes(s) +
                 underflow_note(s);
        return {};
      },
      "");
}

CLI::Validator path_name() {
  return CLI::Validator([](std::string& s) { return s.empty() ? std::string("needs a path, not an empty one") : std::string(); },
                        "");
}

CLI::Validator recording_out() {
  return CLI::Validator(
      [](std::string& s) { return s.empty() ? std::string("needs a path, not an empty one") : host::why_inner_mav0(s); }, "");
}

CLI::Validator one_of(const std::vector<std::string>& words) {
  return CLI::Validator(
      [words](std::string& s) -> std::string {
        for (const std::string& w : words)
          if (s == w) return {};
        std::string list;
        for (size_t i = 0; i < words.size(); ++i)
          list += (i == 0 ? "" : i + 1 == words.size() ? " or " : ", ") + in_quotes(words[i]);
        return "must be " + list + ", not " + in_quotes(s);
      },
      "");
}

bool parse_size(const std::string& text, int& w, int& h) {
  const size_t x = text.find('x');
  if (x == std::string::npos) return false;
  long long a = 0, b = 0;
  if (!parse_long(text.substr(0, x), a) || !parse_long(text.substr(x + 1), b)) return false;
  if (a < 1 || b < 1 || a > 1000000 || b > 1000000) return false;
  w = static_cast<int>(a);
  h = static_cast<int>(b);
  return true;
}

CLI::Validator size_wxh(int max_w, int max_h) {
  return CLI::Validator(
      [max_w, max_h](std::string& s) -> std::string {
        int w = 0, h = 0;
        if (!parse_size(s, w, h) || w > max_w || h > max_h) {
          const size_t x = s.find('x');
          const bool zero = x != std::string::npos && (has_leading_zero(s.substr(0, x)) || has_leading_zero(s.substr(x + 1)));
          return "must be WxH with W in 1.." + std::to_string(max_w) + " and H in 1.." + std::to_string(max_h) +
                 " (e.g. 40x30)" + leading_zero_note(zero) + space_note(s) + ", not " + in_quotes(s);
        }
        return {};
      },
      "");
}

std::string number_text(double v) {
  char b[64];
  for (int digits = 6; digits <= 17; ++digits) {
    std::snprintf(b, sizeof b, "%.*g", digits, v);
    if (std::strtod(b, nullptr) == v || !std::isfinite(v)) break;
  }
  return b;
}

}  // namespace lumavel::cli
