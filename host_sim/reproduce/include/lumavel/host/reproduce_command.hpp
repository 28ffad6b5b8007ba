// `lumavel-sim reproduce`: renders and runs the paper's studies and writes
// docs/results.md (the paper's figures and ours side by side, both engines).
#pragma once
#include "lumavel/host/cli_fwd.hpp"

namespace lumavel::host {

// Adds `reproduce` to lumavel-sim (exit status 0 done, 1 failure, 2 usage).
void add_reproduce_command(cli::Tool& tool);

}  // namespace lumavel::host
