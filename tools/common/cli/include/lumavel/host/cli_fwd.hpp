// The command-line tool's name alone, for headers that declare a command's
// add_*_command(cli::Tool&): CLI11 (lumavel/host/cli.hpp) is compiled only
// by the command's own source, not by every file that includes the header.
#pragma once

namespace lumavel::cli {
class Tool;
}  // namespace lumavel::cli
