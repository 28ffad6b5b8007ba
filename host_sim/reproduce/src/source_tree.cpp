#include "source_tree.hpp"

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <thread>

#ifndef LUMAVEL_SOURCE_DIR
#define LUMAVEL_SOURCE_DIR ""
#endif

namespace lumavel::host::reproduce {
namespace fs = std::filesystem;
namespace {

bool is_source_tree(const fs::path& p) {
  std::error_code ec;
  return fs::is_directory(p / "host_sim" / "scenarios", ec) && fs::is_directory(p / "docs", ec) &&
         fs::is_regular_file(p / "CMakeLists.txt", ec);
}

}  // namespace

std::string source_tree() {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec)
    for (fs::path p = exe.parent_path(); !p.empty(); p = p.parent_path()) {
      if (is_source_tree(p)) return p.string();
      if (p == p.root_path()) break;
    }
  const fs::path built_from = LUMAVEL_SOURCE_DIR;
  if (!built_from.empty() && is_source_tree(built_from)) return built_from.string();
  throw std::runtime_error("cannot find the lumavel source tree (host_sim/scenarios/, docs/) above " +
                           exe.string() + " nor at " + built_from.string() +
                           ": give --scenarios DIR, --doc FILE and --out DIR");
}

std::string machine_description() {
  const unsigned cpus = std::thread::hardware_concurrency();
  std::string model;
  std::ifstream in("/proc/cpuinfo");
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("model name", 0) != 0) continue;
    const size_t colon = line.find(':');
    if (colon != std::string::npos) model = line.substr(line.find_first_not_of(" \t", colon + 1));
    break;
  }
  std::string d = cpus ? std::to_string(cpus) + (cpus == 1 ? " CPU" : " CPUs") : std::string("an unknown number of CPUs");
  if (!model.empty()) d += ", " + model;
  return d;
}

}  // namespace lumavel::host::reproduce
