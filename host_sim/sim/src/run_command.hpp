// `lumavel-sim run`: the command line and the report around run_recording().
#pragma once

namespace lumavel::cli {
class Tool;  // lumavel/host/cli.hpp (CLI11): only the command's own source needs it
}  // namespace lumavel::cli

namespace lumavel::host {

// Adds `run` to lumavel-sim. Exit status: 0 ok, 1 bad recording or failure, 2 usage.
void add_run_command(cli::Tool& tool);

}  // namespace lumavel::host
