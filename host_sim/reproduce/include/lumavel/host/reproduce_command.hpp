// `lumavel-sim reproduce`: renders and runs the paper's studies and writes
// docs/results.md (the paper's figures and ours side by side, both engines).
#pragma once

namespace lumavel::host {

// argv[0] is "reproduce". Returns the exit code (0 done, 1 failure, 2 usage).
int reproduce_main(int argc, char** argv);

}  // namespace lumavel::host
