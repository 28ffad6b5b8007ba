// libFuzzer target for the scenario loader (issue 15): any text either loads
// or throws ScenarioError ("FILE:LINE: what"); any other exception, a crash
// or a sanitizer report is a finding. Seeded with host_sim/scenarios.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "lumavel/host/render/scenario_loader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t len) {
  // The loader takes a path: the input goes to one per-process file.
  static const std::string path = "/tmp/lumavel_fuzz_scenario_" + std::to_string(::getpid()) + ".yaml";
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (f == nullptr) std::abort();
  if (len > 0 && std::fwrite(data, 1, len, f) != len) std::abort();
  std::fclose(f);
  try {
    lumavel::host::render::load_scenario(path);
  } catch (const lumavel::host::render::ScenarioError&) {
    // refused, naming the file and line: the expected outcome for bad input
  }
  return 0;
}
