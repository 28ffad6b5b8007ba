// Where `reproduce` reads its scenarios and writes its page: the lumavel
// source tree, found from the binary, never from the current folder.
#pragma once
#include <string>

namespace lumavel::host::reproduce {

// The source tree holding this binary's build folder (its ancestors are
// searched for host_sim/scenarios/ and docs/), else the one it was built
// from. Throws std::runtime_error saying which options to give when neither
// is there.
std::string source_tree();

// "2 CPUs, Intel(R) Xeon(R) ...": what the figures were measured on.
std::string machine_description();

}  // namespace lumavel::host::reproduce
