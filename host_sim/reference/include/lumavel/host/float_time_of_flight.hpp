// The double twin of firmware/core/time_of_flight.hpp: the same history, the
// same search and the same tracker, with no quantisation (read the core's
// header for what it does and why).
#pragma once
#include <Eigen/Dense>
#include <cstdint>
#include <vector>

namespace lumavel::host {

struct FloatTofFrame {
  uint64_t t_ns = 0;
  double heading = 0;          // rad, unwrapped, offset-corrected
  Eigen::VectorXd f[2], r[2];  // each camera's F and dF/dtheta
  double y = 0;                // integral of the differential observer's V, m
};

struct FloatTofResult {
  bool ok = false;
  bool held = false;   // no match, the track kept (the core's)
  int direction = 0;   // +1: cam0 trails (+h since the match), -1: cam1 trails
  double tau_ns = 0;
  double v = 0;        // m/s
  double sig = 0;      // relative uncertainty of v
  double y_then = 0;
  double turn = 0;     // rad: the gyro's rotation over the window, frame by frame in absolute value
  int frames = 0;      // frames the track has held since it was taken (the core's, saturating)
};

class FloatTimeOfFlight {
 public:
  void reset();
  void push(const FloatTofFrame& frame);
  // direction: the images' direction of travel (FloatImageDirection), 0 unknown.
  FloatTofResult track(int direction, double baseline, double max_rotation, double v_fused, double v_direct);

 private:
  struct Candidate {
    double stau_ns = 0, res = 0, sig_ns = 0, y_then = 0, turn = 0;
  };
  const FloatTofFrame& at(size_t back) const;
  bool search(int trail, double max_rotation, double want_ns, double min_ns, double max_ns, Candidate& out) const;
  double chord_time(int lead, size_t back, const Eigen::VectorXd& d, double dd, double fr) const;  // (the core's)
  // The newest segment's stereo cubic (the core's): its fraction on the same Q16 grid, and its squared residual.
  bool stereo_cubic(int trail, double fr, double* s_out, double* res_out) const;

  std::vector<FloatTofFrame> ring_;  // capacity kTofFrames, oldest first
  double track_ns_ = 0;
  int misses_ = 255;
  int track_frames_ = 0;  // as the core (saturating at 255)
  int acquire_count_ = 0;
  int acquire_gap_ = 0;
  double acquire_ns_ = 0;
  uint64_t track_t_ns_ = 0;  // the newest frame's time when a track last held (read only once held_once_)
  bool held_once_ = false;   // a track has held since the history began
};

}  // namespace lumavel::host
