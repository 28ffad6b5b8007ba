// A gyro sample that leaves both its neighbours and comes back within one
// sample period is a read glitch (a bus error, a corrupted register), not a
// turn: an out-and-back excursion of more than kGyroGlitchMinRadS (at 200 Hz,
// 200 rad/s^2 each way) that stands kGyroGlitchScatters times out of the
// sample-to-sample scatter around it. Vibration raises that scatter and is
// left alone; a turn that starts or stops does not come back. Such a sample,
// integrated, would turn the rig's heading by its excursion times a period
// (30 rad/s over 5 ms: 0.15 rad) and read as image motion: a near-clutter pass
// went 2.42 -> 3.20 % with one such sample, its worst error 0.11 -> 0.49 m/s,
// flagged by nothing. It is replaced by its neighbours' mean and counted.
#pragma once
#include <string>
#include <vector>

#include "lumavel/host/recording.hpp"

namespace lumavel::host {

constexpr double kGyroGlitchMinRadS = 1.0;
constexpr double kGyroGlitchScatters = 20.0;
// Sample-to-sample differences each side of the sample that measure the scatter
// (those touching the sample left out); fewer than half of them: not checked.
constexpr int kGyroGlitchWindow = 8;

struct GyroGlitches {
  int count = 0;
  size_t first_index = 0;   // of the first one in the samples (line index + 2 of imu0/data.csv)
  int first_axis = 0;       // 0..2: w_RS_S_x, _y, _z
  double first_value = 0, first_before = 0, first_after = 0;
};

// Replaces each glitched value of `samples` (w only) by its neighbours' mean;
// neighbours across a gyro hole (an interval over kGapPeriods x period_s) are
// not neighbours.
GyroGlitches repair_gyro_glitches(std::vector<ImuSample>& samples, double period_s);

// "1 gyro value taken as a read glitch and replaced by its neighbours' mean
// (at IMU_CSV:802, w_RS_S_z 30 rad/s between 0.019 and 0.0157: ...)".
std::string format_gyro_glitches(const GyroGlitches& g, const std::string& imu_csv);

}  // namespace lumavel::host
