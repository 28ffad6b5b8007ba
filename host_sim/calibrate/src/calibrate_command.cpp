#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <string>

#include "lumavel/host/calibrate.hpp"
#include "lumavel/host/rig.hpp"

namespace lumavel::host {
namespace {

const char* const kHelp =
    "usage: lumavel-sim calibrate REC [--width W] [--max-shift DEG]\n"
    "\n"
    "Estimates the misalignment (yaw from cam0 to cam1) of the rig that recorded\n"
    "REC, from the images and the gyro alone: where cam0 later stands where cam1\n"
    "stood, the two views differ by the misalignment plus the measured heading\n"
    "change. The rig must move past a textured scene. Prints the estimate with its\n"
    "uncertainty, the value in the recording's sensor.yaml for comparison, and the\n"
    "lumavel-read command that sends it to a board.\n"
    "\n"
    "  --width W         working columns for the registration (default 160)\n"
    "  --max-shift DEG   largest misalignment searched (default 6)\n"
    "\n"
    "exit status: 0 done, 1 bad recording or nothing registered, 2 usage error\n";

}  // namespace

int calibrate_main(int argc, char** argv) {
  std::string rec_dir;
  CalibrationOptions opt;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    try {
      if (a == "-h" || a == "--help") {
        std::fputs(kHelp, stdout);
        return 0;
      } else if (a == "--width" && i + 1 < argc) {
        opt.width = std::stoi(argv[++i]);
        if (opt.width < 16 || opt.width > 160) throw std::invalid_argument("--width must be 16..160");
      } else if (a == "--max-shift" && i + 1 < argc) {
        opt.max_shift_deg = std::stod(argv[++i]);
        if (!(opt.max_shift_deg > 0 && opt.max_shift_deg <= 20)) throw std::invalid_argument("--max-shift must be in (0, 20] deg");
      } else if (!a.empty() && a[0] == '-') {
        throw std::invalid_argument("unknown option '" + a + "'");
      } else if (rec_dir.empty()) {
        rec_dir = a;
      } else {
        throw std::invalid_argument("unexpected argument '" + a + "'");
      }
    } catch (const std::exception& e) {
      std::fprintf(stderr, "lumavel-sim calibrate: %s\n(see lumavel-sim calibrate --help)\n", e.what());
      return 2;
    }
  }
  if (rec_dir.empty()) {
    std::fprintf(stderr, "lumavel-sim calibrate: missing the recording folder REC\n");
    return 2;
  }
  try {
    const Recording rec = load_recording(rec_dir);
    const Calibration c = calibrate_misalignment(rec, opt);
    const EstimatorSettings s = derive_settings(rec, {std::min(opt.width, rec.cam[0].width), 1});
    const double in_yaml = s.cam[1].axis_yaw - s.cam[0].axis_yaw;
    std::printf("misalignment: %.4f deg +- %.4f deg (%zu of %zu frames registered)\n", c.misalignment * 180 / M_PI,
                c.uncertainty * 180 / M_PI, c.samples, c.candidates);
    std::printf("sensor.yaml says: %.4f deg\n", in_yaml * 180 / M_PI);
    std::printf("send to a board: lumavel-read config set misalignment_rad=%.6f\n", c.misalignment);
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "lumavel-sim calibrate: %s\n", e.what());
    return 1;
  }
}

}  // namespace lumavel::host
