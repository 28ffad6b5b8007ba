// The single-camera slider recordings of the Event-Camera Dataset (Mueggler et
// al., IJRR 2017), e.g. slider_depth: images.txt (time s, file), groundtruth.txt
// (t x y z qx qy qz qw) and calib.txt (fx fy cx cy k1 k2 p1 p2 k3). Read as
// they are; errors name the file and the line.
#pragma once
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace lumavel::host {

// A dataset time (s) as the nanoseconds of the recording made from it, to
// the nearest: the one conversion, so that times the reader finds
// increasing are increasing where they are written.
inline uint64_t slider_time_ns(double t_s) { return static_cast<uint64_t>(std::llround(t_s * 1e9)); }

struct SliderFrame {
  double t = 0;      // s
  std::string path;  // absolute or relative to the current directory
  long line = 0;     // in images.txt
};

struct SliderPose {
  double t = 0;                // s
  double p[3] = {0, 0, 0};     // camera position, m (dataset world frame)
  double q[4] = {0, 0, 0, 1};  // qx qy qz qw as in the file
  long line = 0;               // in groundtruth.txt
};

struct SliderCalib {
  double fx = 0, fy = 0, cx = 0, cy = 0;
  double k1 = 0, k2 = 0, p1 = 0, p2 = 0, k3 = 0;
};

struct SliderDataset {
  std::vector<SliderFrame> frames;  // times strictly increasing, to the nanosecond
  std::vector<SliderPose> poses;    // times strictly increasing, to the nanosecond
  SliderCalib calib;
};

// What DIR is, in the reasons a path is refused ("does not exist", "is a
// file, not a dataset folder (...)").
constexpr const char* kSliderDatasetFolder = "dataset folder (images.txt, groundtruth.txt, calib.txt)";

// Reads DIR/images.txt, DIR/groundtruth.txt, DIR/calib.txt (images are not
// decoded here). Throws RecordingError naming the file and line; a position
// beyond the ground truth's physical bound (groundtruth.hpp) is refused; a
// DIR that is no folder is refused by its own name.
SliderDataset read_slider_dataset(const std::string& dir);

}  // namespace lumavel::host
