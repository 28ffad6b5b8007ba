// File names and data.csv column names of the EuRoC/ASL layout, shared by the
// reader and the writer so the two cannot drift apart.
#pragma once
#include <string>
#include <vector>

namespace lumavel::host::layout {

inline const char* const kCamDir[2] = {"cam0", "cam1"};
inline const char* const kImuDir = "imu0";
inline const char* const kGroundTruthDir = "state_groundtruth_estimate0";

// Header columns after "#timestamp [ns]". Functions, not globals, so that
// code running during static initialisation sees them filled.
inline const std::vector<std::string>& cam_columns() {
  static const std::vector<std::string> v = {"filename"};
  return v;
}
inline const std::vector<std::string>& imu_columns() {
  static const std::vector<std::string> v = {
    "w_RS_S_x [rad s^-1]", "w_RS_S_y [rad s^-1]", "w_RS_S_z [rad s^-1]",
    "a_RS_S_x [m s^-2]",   "a_RS_S_y [m s^-2]",   "a_RS_S_z [m s^-2]"};
  return v;
}
// The largest magnitudes an IMU row may hold: far beyond any MEMS part
// (gyros rail near 35-70 rad/s, accelerometers near 4000 m/s^2), so that only
// a corrupt value is refused; a plausible rate beyond the device's range is
// the engines' to flag (SATURATED).
constexpr double kImuMaxRateRadps = 1000;
constexpr double kImuMaxAccelMps2 = 100000;
// The largest magnitudes a ground-truth row may hold (recording and
// import-slider alike), so that a corrupt value is refused rather than
// scored against: a position beyond 1e7 m is farther than any point on Earth
// is from its centre (6.4e6 m, so even Earth-centred coordinates pass); a
// speed beyond 1000 m/s is three times the speed of sound, faster than any
// vehicle this sensor rides on; a quaternion's norm further than 0.01 from 1
// is not a rotation written with a few digits to spare. Biases are bounded
// by the IMU's own limits above.
constexpr double kGroundTruthMaxPositionM = 1e7;
constexpr double kGroundTruthMaxSpeedMps = 1000;
constexpr double kGroundTruthQuaternionNormTolerance = 0.01;
// Ground truth is interpolated at a frame only between two samples at most
// this many of its median intervals apart: across a longer hole (a stretch
// the motion capture lost) the motion is unknown, and a straight line through
// it made up the truth of every frame inside, scored in E as if measured.
constexpr double kGroundTruthMaxHoleIntervals = 10;
// The velocity is what V is compared with, and the positions say what it
// must be: over stretches of kGroundTruthRateStretchS (none across a hole),
// the velocity integrated must reach where the positions go. A stretch may
// be kGroundTruthRateSlackM apart (a motion capture's noise and a filter's
// lag), and beyond that the stretches together at most
// kGroundTruthRateApartShare of the larger travel: zeros where a tool had no
// velocity, or a velocity in km/h or in the body frame of a turning rig, are
// far beyond it; a real estimate (EuRoC's, a slider's, a render's) within a
// thousandth of it.
constexpr double kGroundTruthRateStretchS = 0.5;
constexpr double kGroundTruthRateSlackM = 0.01;
constexpr double kGroundTruthRateApartShare = 0.5;

inline const std::vector<std::string>& groundtruth_columns() {
  static const std::vector<std::string> v = {
    "p_RS_R_x [m]",          "p_RS_R_y [m]",          "p_RS_R_z [m]",          "q_RS_w []",
    "q_RS_x []",             "q_RS_y []",             "q_RS_z []",             "v_RS_R_x [m s^-1]",
    "v_RS_R_y [m s^-1]",     "v_RS_R_z [m s^-1]",     "b_w_RS_S_x [rad s^-1]", "b_w_RS_S_y [rad s^-1]",
    "b_w_RS_S_z [rad s^-1]", "b_a_RS_S_x [m s^-2]",   "b_a_RS_S_y [m s^-2]",   "b_a_RS_S_z [m s^-2]"};
  return v;
}

}  // namespace lumavel::host::layout
