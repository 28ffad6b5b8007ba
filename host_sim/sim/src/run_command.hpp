// `lumavel-sim run`: argument parsing and reporting around run_recording().
#pragma once

namespace lumavel::host {

// argv[0] is "run". Exit status: 0 ok, 1 bad recording or failure, 2 usage.
int run_main(int argc, char** argv);

}  // namespace lumavel::host
