// `lumavel-sim render SCENARIO.yaml OUT/`: renders a synthetic stereo + gyro
// recording (the recording format: docs/recording-format.md; scenario keys:
// host_sim/scenarios/README.md) from a YAML scenario.
#pragma once
#include "lumavel/host/cli_fwd.hpp"

namespace lumavel::host {

// Adds `render` to lumavel-sim: exit status 0 on success, 1 on bad input
// (message on stderr naming file and line), 2 on bad usage.
void add_render_command(cli::Tool& tool);

// The command alone; argv[0] is "render". Never throws.
int render_main(int argc, char** argv);

}  // namespace lumavel::host
