// `lumavel-sim run`: the command line and the report around run_recording().
#pragma once
#include "lumavel/host/cli_fwd.hpp"

namespace lumavel::host {

// Adds `run` to lumavel-sim. Exit status: 0 ok, 1 bad recording or failure, 2 usage.
void add_run_command(cli::Tool& tool);

}  // namespace lumavel::host
