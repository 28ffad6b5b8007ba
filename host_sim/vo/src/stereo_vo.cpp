#include "lumavel/host/vo/stereo_vo.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "lumavel/core/status.hpp"
#include "lumavel/host/vo/translation_solver.hpp"

namespace lumavel::host::vo {
namespace {

double seconds(uint64_t later, uint64_t earlier) {
  return (static_cast<double>(later) - static_cast<double>(earlier)) * 1e-9;
}

cv::Matx33d rot_z(double a) {
  const double c = std::cos(a), s = std::sin(a);
  return cv::Matx33d(c, -s, 0, s, c, 0, 0, 0, 1);
}

}  // namespace

StereoVo::StereoVo(const StereoRig& rig, const VoParams& params)
    : p_(params), geo_(rig), front_(rig.width, rig.height, params) {
  f_px_[0] = geo_.focal_px(0);
  f_px_[1] = geo_.focal_px(1);
}

double StereoVo::median_depth() const {
  if (tracks_.empty()) return 0;  // unknown: infinitely far
  std::vector<double> z;
  z.reserve(tracks_.size());
  for (const Track& t : tracks_) z.push_back(t.X[2]);
  std::nth_element(z.begin(), z.begin() + static_cast<std::ptrdiff_t>(z.size() / 2), z.end());
  return z[z.size() / 2];
}

std::vector<StereoVo::Track> StereoVo::stereo_tracks(const std::vector<cv::Point2f>& p0,
                                                     const std::vector<cv::Point2f>& guess1) const {
  std::vector<Track> out;
  std::vector<uint8_t> ok;
  const std::vector<cv::Point2f> p1 = front_.match_stereo(p0, guess1, ok);
  std::vector<cv::Point2f> a, b;
  for (size_t i = 0; i < p0.size(); ++i)
    if (ok[i]) {
      a.push_back(p0[i]);
      b.push_back(p1[i]);
    }
  const std::vector<cv::Point2d> n0 = geo_.normalise(0, a), n1 = geo_.normalise(1, b);
  std::vector<uint8_t> in_front;
  const std::vector<cv::Vec3d> X = geo_.triangulate(n0, n1, in_front);
  const double max_depth = p_.max_depth_baselines * geo_.rig().baseline;
  for (size_t i = 0; i < a.size(); ++i)
    if (in_front[i] && X[i][2] <= max_depth && geo_.epipolar_px(n0[i], n1[i]) <= p_.max_epipolar_px)
      out.push_back({{a[i], b[i]}, X[i]});
  return out;
}

void StereoVo::replenish() {
  const int want = p_.max_features - static_cast<int>(tracks_.size());
  if (static_cast<double>(tracks_.size()) >= p_.redetect_fraction * p_.max_features || want <= 0) return;
  std::vector<cv::Point2f> existing;
  for (const Track& t : tracks_) existing.push_back(t.px[0]);
  std::vector<cv::Point2f> fresh = front_.detect(existing, want);
  const std::vector<cv::Point2d> n0 = geo_.normalise(0, fresh);
  // Stereo search from the depth most tracks have (infinitely far when
  // there are none): the pyramid reaches disparities up to about
  // window/2 * 2^levels pixels around it. No other starting depths: on
  // periodic texture a start near a wrong period converges there, and the
  // epipolar test cannot see an error along the line.
  std::vector<cv::Point2f> guess;
  guess.reserve(fresh.size());
  const double depth = median_depth();
  for (const cv::Point2d& n : n0) guess.push_back(cam1_guess(n, depth));
  for (const Track& t : stereo_tracks(fresh, guess)) tracks_.push_back(t);
}

bool StereoVo::measure(double yaw, double dt, double& v_direct, int& inliers) {
  inliers = 0;
  if (tracks_.empty()) return false;
  std::vector<cv::Point2f> prev[2];
  for (int c = 0; c < 2; ++c)
    for (const Track& t : tracks_) prev[c].push_back(t.px[c]);
  std::vector<uint8_t> ok[2];
  const std::vector<cv::Point2f> now0 = front_.track(0, prev[0], ok[0]);
  const std::vector<cv::Point2f> now1 = front_.track(1, prev[1], ok[1]);
  std::vector<size_t> alive;
  std::vector<cv::Point2f> a, b;
  for (size_t i = 0; i < tracks_.size(); ++i)
    if (ok[0][i] && ok[1][i]) {
      alive.push_back(i);
      a.push_back(now0[i]);
      b.push_back(now1[i]);
    }
  const std::vector<cv::Point2d> n0 = geo_.normalise(0, a), n1 = geo_.normalise(1, b);
  std::vector<MotionObservation> obs(alive.size());
  for (size_t k = 0; k < alive.size(); ++k) obs[k] = {tracks_[alive[k]].X, {n0[k], n1[k]}};

  // The body turned by `yaw` about its z axis: points turn the other way
  // in the body frame, R = R_CB Rz(yaw)^T R_BC in cam0's frame.
  const VoCamera& c0 = geo_.rig().cam[0];
  const cv::Matx33d Rz = rot_z(yaw);
  const cv::Matx33d R = c0.R_BC.t() * Rz.t() * c0.R_BC;
  const TranslationResult tr = solve_translation(obs, R, geo_.rig(), f_px_, p_.inlier_px, p_.inlier_floor_px, p_.min_inliers);

  // Carry the tracks (the motion's inliers when it was measured) to the
  // current frame, re-matching each one's stereo partner from cam0 so that
  // its depth is measured afresh, not accumulated.
  std::vector<cv::Point2f> keep0, keep1;
  for (size_t k = 0; k < alive.size(); ++k)
    if (!tr.ok || tr.inlier[k]) {
      keep0.push_back(a[k]);
      keep1.push_back(b[k]);
    }
  tracks_ = stereo_tracks(keep0, keep1);
  if (!tr.ok) return false;

  // Body displacement: X_B = R_BC X_C + c_B at both frames gives
  // d_B = c_B - Rz (R_BC t + c_B), in the body frame of the previous frame;
  // V is its x component in the frame halfway through the turn.
  const cv::Vec3d d_B = c0.c_B - Rz * (c0.R_BC * tr.t + c0.c_B);
  const cv::Vec3d d_mid = rot_z(-0.5 * yaw) * d_B;
  v_direct = d_mid[0] / dt;
  inliers = tr.inliers;
  return std::isfinite(v_direct);
}

VoEstimate StereoVo::step(uint64_t t_ns, const uint8_t* cam0, const uint8_t* cam1) {
  VoEstimate e;
  e.t_ns = t_ns;
  front_.push_frames(cam0, cam1);
  const bool first = frames_++ == 0;
  const bool forward = !first && t_ns > prev_t_;
  const double dt = forward ? seconds(t_ns, prev_t_) : 0.0;
  double yaw = 0;
  if (forward) {
    const GyroYaw::Interval g = gyro_.between(prev_t_, t_ns);
    yaw = g.yaw;
    if (g.max_spacing > p_.gyro_gap) e.status |= kStatusGyroGap;
  }
  heading_ += yaw;

  const bool dark = front_.mean_level(0) < p_.no_light_mean || front_.mean_level(1) < p_.no_light_mean;
  // One image on both cameras (a driver fault): no stereo, as lumavel's engines flag it.
  const size_t n = static_cast<size_t>(geo_.rig().width) * static_cast<size_t>(geo_.rig().height);
  const bool same = !dark && std::memcmp(cam0, cam1, n) == 0;
  bool measured = false;
  if (forward && dt > 1.5 * geo_.rig().frame_period) e.status |= kStatusFrameGap;
  if (forward && dt > p_.max_gap) {
    e.status |= kStatusRestarted;
    started_ = false;  // V held; the next measurement re-initialises it
  }
  if (dark || same) {
    e.status |= (dark ? kStatusNoLight : kStatusNoStereo) | kStatusLowTexture;
    tracks_.clear();
  } else {
    if (forward && front_.has_previous()) {
      double vd = 0;
      int inl = 0;
      measured = measure(yaw, dt, vd, inl) && dt <= p_.max_gap;
      e.inliers = inl;
      if (measured) e.v_direct = vd;
    } else {
      tracks_.clear();  // time went backwards or first frame: start over
    }
    replenish();
    if (!first && !measured && !(e.status & kStatusRestarted)) e.status |= kStatusLowTexture;
    if (first && tracks_.empty()) e.status |= kStatusLowTexture;
  }

  if (measured) {
    if (!started_) {
      v_ = e.v_direct;  // the first measurement initialises V: no start-up ramp
      started_ = true;
      since_start_ = 0;
    } else {
      v_ += (e.v_direct - v_) * dt / (p_.tau + dt);
      since_start_ += dt;
    }
  }
  if (!started_ || since_start_ < 3 * p_.tau) e.status |= kStatusConverging;
  distance_ += v_ * dt;
  if (forward || first) prev_t_ = t_ns;
  e.v = v_;
  e.distance = distance_;
  e.heading = std::remainder(heading_, 2 * M_PI);
  if (e.heading >= M_PI) e.heading -= 2 * M_PI;
  e.tracks = static_cast<int>(tracks_.size());
  return e;
}

}  // namespace lumavel::host::vo
