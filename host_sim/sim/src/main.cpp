// lumavel-sim: host tools over recordings (run the estimator, render scenes,
// reproduce the paper, calibrate, import), one CLI11 subcommand each.
#include "lumavel/host/calibrate.hpp"
#include "lumavel/host/cli.hpp"
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

int main(int argc, char** argv) {
  lumavel::cli::Tool tool("lumavel-sim",
                          "Host tools of lumavel (curvilinear velocity from two low-resolution cameras\n"
                          "and a yaw gyro) over recordings in the EuRoC/ASL layout\n"
                          "(docs/recording-format.md). `lumavel-sim COMMAND --help` describes each command.",
                          LUMAVEL_VERSION);
  lumavel::host::add_run_command(tool);
#if LUMAVEL_HAVE_RENDER
  lumavel::host::add_render_command(tool);
#endif
  lumavel::host::add_reproduce_command(tool);
  lumavel::host::add_calibrate_command(tool);
  lumavel::host::add_import_slider_command(tool);
  return tool.run(argc, argv);
}
