#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <fstream>
#include <string>

#include "lumavel/host/calibrate.hpp"
#include "lumavel/host/device_setup_from_rig.hpp"
#include "lumavel/host/rig.hpp"

namespace lumavel::host {
namespace {

const char* const kHelp =
    "usage: lumavel-sim calibrate REC [--width W] [--max-shift DEG] [--write FILE [--write-size WxH]]\n"
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
    "  --write FILE      also write the board's whole configuration for this rig,\n"
    "                    with the calibrated misalignment and the lens tables from\n"
    "                    sensor.yaml, as KEY=VALUE lines for\n"
    "                    `lumavel-read config set --file FILE`\n"
    "  --write-size WxH  working resolution of that configuration (default 40x30;\n"
    "                    a line-scan recording gets height 1)\n"
    "\n"
    "exit status: 0 done, 1 bad recording or nothing registered, 2 usage error\n";

}  // namespace

int calibrate_main(int argc, char** argv) {
  std::string rec_dir, write_path;
  WorkingSize write_size;
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
      } else if (a == "--write" && i + 1 < argc) {
        write_path = argv[++i];
      } else if (a == "--write-size" && i + 1 < argc) {
        const std::string v = argv[++i];
        size_t x = v.find('x'), end = 0;
        if (x == std::string::npos) throw std::invalid_argument("--write-size wants WxH, e.g. 128x1");
        write_size.width = std::stoi(v.substr(0, x), &end);
        if (end != x) throw std::invalid_argument("--write-size wants WxH, e.g. 128x1");
        write_size.height = std::stoi(v.substr(x + 1), &end);
        if (end != v.size() - x - 1) throw std::invalid_argument("--write-size wants WxH, e.g. 128x1");
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
    if (write_path.empty()) {
      std::printf("send to a board: lumavel-read config set misalignment_rad=%.6f\n", c.misalignment);
      return 0;
    }
    const DeviceSetup setup = device_setup_from_recording(rec, write_size, c.misalignment);
    std::ofstream out(write_path, std::ios::binary | std::ios::trunc);
    out << "# lumavel device configuration for " << rec_dir << " (lumavel-sim calibrate --write)\n"
        << "# send with: lumavel-read config set --file " << write_path << "\n"
        << format_setup(setup);
    out.close();
    if (!out) throw std::runtime_error(write_path + ": cannot write the configuration file");
    std::printf("wrote %s (%dx%d, lens tables: %s); send to a board: lumavel-read config set --file %s\n",
                write_path.c_str(), setup.config.width, setup.config.height,
                setup.config.lens == 0 ? "none, pinhole" : setup.config.lens == 3 ? "both cameras" : "one camera",
                write_path.c_str());
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "lumavel-sim calibrate: %s\n", e.what());
    return 1;
  }
}

}  // namespace lumavel::host
