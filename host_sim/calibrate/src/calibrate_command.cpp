// Command line of `lumavel-sim calibrate`.
#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>

#include "lumavel/host/calibrate.hpp"
#include "lumavel/host/cli.hpp"
#include "lumavel/host/device_setup_from_rig.hpp"
#include "lumavel/host/output_file.hpp"
#include "lumavel/host/path_check.hpp"
#include "lumavel/host/progress.hpp"
#include "lumavel/host/rig.hpp"
#include "lumavel/host/rig_settings_check.hpp"

namespace lumavel::host {
namespace {

const char* const kDescription =
    "estimate the misalignment between the cameras from a recording\n\n"
    "Estimates the misalignment (yaw from cam0 to cam1) of the rig that recorded\n"
    "REC, from the images and the gyro alone: where cam0 later stands where cam1\n"
    "stood, the two views differ by the misalignment plus the measured heading\n"
    "change. The rig must move past a textured scene. Prints the working size used,\n"
    "the estimate with its uncertainty, the value in the recording's sensor.yaml for\n"
    "comparison, and the lumavel-read command that sends it to a board; with an\n"
    "uncertainty above 0.1 deg it suggests nothing, writes nothing and exits 1.\n"
    "Progress goes to standard error.";

// A misalignment is suggested for a board (printed as a config set command
// or written by --write) only with an uncertainty at most this (issue 15):
// a 0.1 deg yaw error is about 1 % of V on the paper's rig.
constexpr double kMaxSuggestedUncertaintyDeg = 0.1;

// The registration is validated at this many columns (docs/results.md);
// coarser recordings are registered at their own width, with a warning.
constexpr int kRegistrationColumns = 160;

struct CalibrateArgs {
  std::string rec, write_path, write_size;
  int width = 0;  // --width; 0: the default, kRegistrationColumns or the sensor's width when smaller
  CalibrationOptions opt;
  bool quiet = false;
};

// Progress of the two stages, one cli::Progress each.
class StageProgress {
 public:
  void operator()(const char* stage, size_t done, size_t total) {
    if (stage_ != stage) {
      if (bar_) bar_->finish();
      stage_ = stage;
      bar_ = std::make_unique<cli::Progress>(static_cast<long>(total), std::string("calibrate: ") + stage);
    }
    bar_->update(static_cast<long>(done));
  }
  void finish() {
    if (bar_) bar_->finish();
    bar_.reset();
  }

 private:
  std::string stage_;
  std::unique_ptr<cli::Progress> bar_;
};

int calibrate(CalibrateArgs& a) {
  if (!a.write_size.empty() && a.write_path.empty()) throw cli::UsageError("--write-size needs --write FILE");
  if (!a.write_path.empty())  // refused before the registration, not after it
    if (const std::string why = why_not_writable(a.write_path, "configuration file"); !why.empty())
      throw std::runtime_error(shown_path(a.write_path) + " (--write): " + why);
  const Recording rec = load_recording(a.rec);
  // --width wider than the sensor is refused by run's rule, naming the
  // sensor.yaml (was: registered at the sensor's width with a warning, where
  // run refuses); only the default is cut to a narrower sensor.
  // Its hint names --width alone: calibrate has no --height (was: 'choose a
  // smaller --width/--height').
  if (a.width > 0) check_bins_down(rec, {a.width, rec.cam[0].height}, "--width");
  a.opt.width = a.width > 0 ? a.width : std::min(kRegistrationColumns, rec.cam[0].width);
  if (!a.write_path.empty() && overwrites_recording(rec, a.write_path))
    throw cli::UsageError(shown_path(a.write_path) + " (--write): that is part of the recording being read (" +
                          shown_path(rec.root) + "); write the configuration elsewhere");
  // Its report on standard output too, as run's CSV: 'calibrate rec >>
  // rec/mav0/cam0/sensor.yaml' appended the report to the sensor.yaml it had
  // read, exit 0 (the recording then refused: 'registered' is no key).
  const std::string so = standard_output_file();
  if (!so.empty() && overwrites_recording(rec, so))
    throw cli::UsageError(shown_path(so) + " (standard output): that is part of the recording being read (" +
                          shown_path(rec.root) + "); send the report elsewhere");
  // ... nor the --write file, as run's outputs: 'calibrate rec --write w.cfg >
  // w.cfg' wrote the configuration over the report (the shell had opened the
  // file first), exit 0, the report lost.
  if (!so.empty() && !a.write_path.empty()) {
    const std::string at = written_path(a.write_path);
    if (!at.empty() && at == written_path(so))
      throw cli::UsageError(shown_path(a.write_path) + ": standard output (the report) and --write name the same file");
  }
  WorkingSize write_size = default_working_size(rec);
  if (!a.write_size.empty()) {
    cli::parse_size(a.write_size, write_size.width, write_size.height);
    const CameraSensor& s = rec.cam[0];
    if (write_size.width < kMinWorkWidth || write_size.width > std::min(kMaxWorkWidth, s.width) ||
        write_size.height < 1 || write_size.height > std::min(kMaxWorkHeight, s.height))
      throw cli::UsageError("--write-size " + a.write_size + ": the working size must be " +
                            std::to_string(kMinWorkWidth) + ".." + std::to_string(std::min(kMaxWorkWidth, s.width)) +
                            " x 1.." + std::to_string(std::min(kMaxWorkHeight, s.height)) +
                            " (the core's limits and this " + std::to_string(s.width) + "x" +
                            std::to_string(s.height) + " sensor)");
  }
  // The configuration --write will carry, checked by run's rules before the
  // registration (naming the file), not after it with a bare message.
  if (!a.write_path.empty()) check_rig_settings(rec, derive_settings(rec, write_size));
  // run flags the frames of a gap; calibrate has no such column: it says so.
  if (has_gaps(rec.gaps))
    std::fprintf(stderr,
                 "calibrate: warning: %s: %s (the heading is interpolated across a gyro hole; frames beyond the gyro "
                 "read no turn)\n",
                 a.rec.c_str(), format_gaps(rec.gaps).c_str());
  const int columns = a.opt.width;
  if (columns < kRegistrationColumns)
    std::fprintf(stderr,
                 "calibrate: warning: registering at %d columns (%s)\n"
                 "calibrate: warning: calibrate is validated at %d columns (docs/results.md); on coarser images\n"
                 "  its estimate and its uncertainty are less reliable\n",
                 columns,
                 a.width == 0 ? ("the sensor's width: " + a.rec + " has " + std::to_string(rec.cam[0].width) +
                                          " columns").c_str()
                                       : "--width",
                 kRegistrationColumns);
  auto stages = std::make_shared<StageProgress>();
  if (!a.quiet) a.opt.progress = [stages](const char* s, size_t d, size_t t) { (*stages)(s, d, t); };
  Calibration c;
  try {
    c = calibrate_misalignment(rec, a.opt);
  } catch (...) {
    stages->finish();
    throw;
  }
  stages->finish();
  const EstimatorSettings s = derive_settings(rec, {a.opt.width, 1});
  const double in_yaml = s.cam[1].axis_yaw - s.cam[0].axis_yaw;
  std::printf("registered at %dx%d (the %dx%d sensor%s)\n", c.width, c.height, rec.cam[0].width,
              rec.cam[0].height, c.width < rec.cam[0].width ? " binned" : "'s own size");
  std::printf("misalignment: %.4f deg +- %.4f deg (%zu of %zu frames registered)\n", c.misalignment * 180 / M_PI,
              c.uncertainty * 180 / M_PI, c.samples, c.candidates);
  if (c.same_image > 0)
    std::printf("skipped: %zu frames where both cameras delivered the same image (no stereo difference)\n",
                c.same_image);
  std::printf("sensor.yaml says: %.4f deg\n", in_yaml * 180 / M_PI);
  const double uncertainty_deg = c.uncertainty * 180 / M_PI;
  if (!(uncertainty_deg <= kMaxSuggestedUncertaintyDeg)) {
    char why[512];
    std::snprintf(why, sizeof why,
                  "not suggested for a board: the uncertainty, %.4f deg, is above %.1f deg%s (register at more "
                  "columns, up to %d, or record a longer pass past a textured scene)",
                  uncertainty_deg, kMaxSuggestedUncertaintyDeg, a.write_path.empty() ? "" : "; nothing written",
                  kRegistrationColumns);
    throw std::runtime_error(why);
  }
  if (a.write_path.empty()) {
    std::printf("send to a board: lumavel-read config set misalignment_rad=%.6f\n", c.misalignment);
    return 0;
  }
  const DeviceSetup setup = device_setup_from_recording(rec, write_size, c.misalignment);
  // The names through shown_path: a line break in one (a recording folder
  // named 'rec<LF>width=160') ended the comment, and the file written, exit 0,
  // held a line 'width=160 (lumavel-sim calibrate --write)' that config set
  // refuses.
  const std::string text = "# lumavel device configuration for " + shown_path(a.rec) +
                           " (lumavel-sim calibrate --write)\n" + "# send with: lumavel-read config set --file " +
                           shown_path(a.write_path) + "\n" + format_setup(setup);
  // A FIFO nobody reads: refused, not waited on. A file that cannot be
  // written whole is not left half-written, to be sent to a board.
  write_file(a.write_path, text, "the configuration file");
  std::printf("wrote %s (%dx%d working, lens tables: %s); send to a board: lumavel-read config set --file %s\n",
              shown_path(a.write_path).c_str(), setup.config.width, setup.config.height,
              setup.config.lens == 0 ? "none, pinhole" : setup.config.lens == 3 ? "both cameras" : "one camera",
              shown_path(a.write_path).c_str());
  return 0;
}

}  // namespace

void add_calibrate_command(cli::Tool& tool) {
  auto a = std::make_shared<CalibrateArgs>();
  CLI::App* c = tool.command("calibrate", kDescription, [a] { return calibrate(*a); });
  c->add_option("REC", a->rec, "the recording folder (REC or REC/mav0)")->required()->type_name("")->check(cli::path_name());
  c->add_option("--width", a->width,
                "working columns for the registration, 16..160 (default " +
                    std::to_string(kRegistrationColumns) + ", or the\nsensor's width when smaller)")
      ->type_name("W")
      ->check(cli::whole_number_in(16, 160));
  c->add_option("--max-shift", a->opt.max_shift_deg, "largest misalignment searched, (0, 20] deg (default 6)")
      ->type_name("DEG")
      ->check(cli::positive_number_up_to(20));
  c->add_option("--write", a->write_path,
                                     "also write the board's whole configuration for this rig,\n"
                                     "with the calibrated misalignment and the lens tables from\n"
                                     "sensor.yaml, as KEY=VALUE lines for\n"
                                     "`lumavel-read config set --file FILE`")
                           ->type_name("FILE")
                           ->check(cli::path_name());
  c->add_option("--write-size", a->write_size,
                "working resolution of that configuration (default 40x30, or\n"
                "the sensor's size when smaller; a line-scan recording gets\n"
                "height 1)")
      ->type_name("WxH")
      ->check(cli::size_wxh(kMaxWorkWidth, kMaxWorkHeight));
  c->add_flag("-q,--quiet", a->quiet, "no progress on standard error");
}

}  // namespace lumavel::host
