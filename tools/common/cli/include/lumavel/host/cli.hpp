// The command lines of lumavel-sim and lumavel-read, on CLI11, with one
// convention for both tools:
// - help generated from the options, "Usage:" first, the exit status last;
// - exit status 0 done, 1 bad input or failure, 2 usage error (tools may add
//   codes above 2 for their own failures);
// - messages "TOOL COMMAND: what", usage errors followed by the help hint.
// Value rules are validators whose messages name the rule and the value, so
// that CLI11 prints "--width: must be a whole number in 16..160, not '12'".
#pragma once
#include <functional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace lumavel::cli {

enum Exit : int { kExitOk = 0, kExitFailure = 1, kExitUsage = 2 };

// The exit status lines shared by every command of a tool without codes of its own.
extern const char* const kExitStatusHelp;

// A usage mistake found after parsing (e.g. two options that exclude each
// other): Tool::run prints it like a parse error, exit 2.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// What a command does once its command line is parsed: the exit status.
using Action = std::function<int()>;

class Tool {
 public:
  // `exit_status` ends every help text (kExitStatusHelp unless a tool has more codes).
  Tool(const std::string& name, const std::string& description, const std::string& version,
       const std::string& exit_status = kExitStatusHelp);
  Tool(const Tool&) = delete;
  Tool& operator=(const Tool&) = delete;

  CLI::App& app() { return app_; }
  // A subcommand of `parent` (the tool or another command). The first
  // paragraph of `description` is its summary in the list of commands. `action` runs
  // when it is the last command named on the line. A command without an
  // action needs a subcommand.
  CLI::App* command(CLI::App& parent, const std::string& name, const std::string& description,
                    Action action = {});
  // Same on the tool itself.
  CLI::App* command(const std::string& name, const std::string& description, Action action = {});

  // Parses, then runs the chosen command's action. Help and --version: 0.
  // A usage error: the message and the help hint on stderr, 2. An exception
  // out of the action: "TOOL COMMAND: error: what" on stderr, 1.
  int run(int argc, const char* const* argv);

 private:
  std::string path_of(const CLI::App* sub) const;

  CLI::App app_;
  std::string exit_status_;
  std::vector<std::pair<CLI::App*, Action>> actions_;
};

// Runs one command of `tool_name` on its own: argv[0] is the command's name
// (for tests and for commands called from other code). Same exit status as
// Tool::run.
int run_command_alone(const std::string& tool_name, const std::function<void(Tool&)>& add, int argc,
                      char** argv);

// Validators (the message names the rule and the value).
CLI::Validator whole_number_in(long long lo, long long hi, const std::string& note = "");  // note: after the range
CLI::Validator number_in(double lo, double hi);            // [lo, hi]
CLI::Validator positive_number_up_to(double hi);           // (0, hi]
CLI::Validator one_of(const std::vector<std::string>& words);
// A file or folder name: not empty (an empty shell variable must not mean the default).
CLI::Validator path_name();
// A recording folder to write (its frames go to OUT/mav0): a path name, and
// not a mav0 folder itself (why_inner_mav0, path_check.hpp).
CLI::Validator recording_out();
// "WxH" with W in 1..max_w and H in 1..max_h.
CLI::Validator size_wxh(int max_w, int max_h);
// Parses "WxH" (both positive); false when the text is not of that form.
bool parse_size(const std::string& text, int& w, int& h);

// A number in the shortest form that reads back the same (%g with enough
// digits): for messages, never 300 digits.
std::string number_text(double v);

}  // namespace lumavel::cli
