// lumavel-sim: host tools over recordings (run the estimator, render scenes).
#include <cstdio>
#include <cstring>

#include "lumavel/host/calibrate.hpp"
#include "lumavel/host/import_slider.hpp"
#include "lumavel/host/reproduce_command.hpp"
#include "run_command.hpp"

#if __has_include("lumavel/host/render_command.hpp")
#include "lumavel/host/render_command.hpp"
#define LUMAVEL_HAVE_RENDER 1
#else
#define LUMAVEL_HAVE_RENDER 0
#endif

#ifndef LUMAVEL_VERSION
#define LUMAVEL_VERSION "unknown"
#endif

namespace {

void print_help(std::FILE* f) {
  std::fputs(
      "usage: lumavel-sim <command> [options]\n"
      "\n"
      "Host tools of lumavel (curvilinear velocity from two low-resolution cameras\n"
      "and a yaw gyro) over recordings in the EuRoC/ASL layout.\n"
      "\n"
      "commands:\n"
      "  run       run the estimator over a recording, write the estimates CSV\n"
#if LUMAVEL_HAVE_RENDER
      "  render    render a synthetic recording of a textured scene\n"
#endif
      "  reproduce render and run the paper's studies, write docs/results.md\n"
      "  calibrate estimate the misalignment between the cameras from a recording\n"
      "  import-slider  turn a single-camera slider sequence into a two-camera recording\n"
      "\n"
      "  lumavel-sim <command> --help   help on one command\n"
      "  lumavel-sim --version          version\n"
      "\n"
      "exit status: 0 done, 1 bad input or failure, 2 usage error\n",
      f);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    print_help(stderr);
    return 2;
  }
  const char* cmd = argv[1];
  if (!std::strcmp(cmd, "-h") || !std::strcmp(cmd, "--help") || !std::strcmp(cmd, "help")) {
    print_help(stdout);
    return 0;
  }
  if (!std::strcmp(cmd, "--version")) {
    std::printf("lumavel-sim %s\n", LUMAVEL_VERSION);
    return 0;
  }
  if (!std::strcmp(cmd, "run")) return lumavel::host::run_main(argc - 1, argv + 1);
#if LUMAVEL_HAVE_RENDER
  if (!std::strcmp(cmd, "render")) return lumavel::host::render_main(argc - 1, argv + 1);
#endif
  if (!std::strcmp(cmd, "calibrate")) return lumavel::host::calibrate_main(argc - 1, argv + 1);
  if (!std::strcmp(cmd, "import-slider")) return lumavel::host::import_slider_main(argc - 1, argv + 1);
  if (!std::strcmp(cmd, "reproduce")) return lumavel::host::reproduce_main(argc - 1, argv + 1);
  std::fprintf(stderr, "lumavel-sim: unknown command '%s' (see lumavel-sim --help)\n", cmd);
  return 2;
}
