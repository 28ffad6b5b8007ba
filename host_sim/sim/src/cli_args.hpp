// Tiny strict argument helpers shared by the subcommands.
#pragma once
#include <stdexcept>
#include <string>

namespace lumavel::host {

// A command-line mistake: the caller prints it with the usage hint, exit 2.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Matches "--name VALUE" and "--name=VALUE"; advances i past the value.
inline bool option_value(int argc, char** argv, int& i, const char* name, std::string& value) {
  const std::string arg = argv[i];
  const std::string n = name;
  if (arg == n) {
    if (i + 1 >= argc) throw UsageError("option " + n + " needs a value");
    value = argv[++i];
    return true;
  }
  if (arg.rfind(n + "=", 0) == 0) {
    value = arg.substr(n.size() + 1);
    return true;
  }
  return false;
}

inline int parse_int(const std::string& text, const char* what) {
  size_t used = 0;
  int v = 0;
  try {
    v = std::stoi(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size()) throw UsageError(std::string(what) + " '" + text + "' is not an integer");
  return v;
}

}  // namespace lumavel::host
