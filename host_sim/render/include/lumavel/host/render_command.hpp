// `lumavel-sim render SCENARIO.yaml OUT/`: renders a synthetic stereo + gyro
// recording (EuRoC layout, docs: /work/shared/spec/recording-format.md and
// host_sim/scenarios/README.md) from a YAML scenario.
#pragma once

namespace lumavel::host {

// argv[0] is the sub-command name ("render"). Returns the process exit code:
// 0 on success, 1 on bad input (message on stderr naming file and line), 2 on
// bad usage. Never throws.
int render_main(int argc, char** argv);

}  // namespace lumavel::host
