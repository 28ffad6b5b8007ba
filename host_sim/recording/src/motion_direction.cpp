#include "lumavel/host/motion_direction.hpp"

#include <algorithm>
#include <cmath>

#include "lumavel/host/path_check.hpp"

namespace lumavel::host {

MotionDirectionCheck::MotionDirectionCheck(int width, int height, int u_sign0, int u_sign1)
    : width_(width), height_(height), u_sign_{u_sign0 < 0 ? -1 : 1, u_sign1 < 0 ? -1 : 1} {
  for (int c = 0; c < 2; ++c) profile_[c].assign(static_cast<size_t>(width), 0.0);
}

int MotionDirectionCheck::shift(const std::vector<double>& now, const std::vector<double>& before) const {
  // now[u] ~ before[u - L]: the content moved by L columns. Lags up to a
  // quarter of the width, each over the columns both profiles share.
  const int max_lag = width_ / 4;
  int best = 0;
  double best_r = -2;
  for (int lag = -max_lag; lag <= max_lag; ++lag) {
    const int from = std::max(0, lag), to = std::min(width_, width_ + lag);
    const int n = to - from;
    if (n < 2) continue;
    double ma = 0, mb = 0;
    for (int u = from; u < to; ++u) {
      ma += now[static_cast<size_t>(u)];
      mb += before[static_cast<size_t>(u - lag)];
    }
    ma /= n;
    mb /= n;
    double ab = 0, aa = 0, bb = 0;
    for (int u = from; u < to; ++u) {
      const double a = now[static_cast<size_t>(u)] - ma, b = before[static_cast<size_t>(u - lag)] - mb;
      ab += a * b;
      aa += a * a;
      bb += b * b;
    }
    const double r = aa > 0 && bb > 0 ? ab / std::sqrt(aa * bb) : 0;
    if (r > best_r) {
      best_r = r;
      best = lag;
    }
  }
  return best_r >= kMotionMinCorrelation ? best : 0;
}

void MotionDirectionCheck::add(const uint8_t* cam0, const uint8_t* cam1) {
  const uint8_t* img[2] = {cam0, cam1};
  int moved[2] = {0, 0};
  for (int c = 0; c < 2; ++c) {
    std::vector<double>& p = profile_[c];
    for (int u = 0; u < width_; ++u) {
      double sum = 0;
      for (int v = 0; v < height_; ++v) sum += img[c][static_cast<size_t>(v) * static_cast<size_t>(width_) + static_cast<size_t>(u)];
      p[static_cast<size_t>(u)] = sum;
    }
    if (have_previous_) moved[c] = shift(p, previous_[c]) * u_sign_[c];
    previous_[c].swap(p);
    p.resize(static_cast<size_t>(width_));
  }
  const bool had_previous = have_previous_;
  have_previous_ = true;
  if (!had_previous) return;
  // One image moved a column or more, the other's did not (stood still, or
  // showed no motion that its previous frame explains).
  for (int c = 0; c < 2; ++c)
    if (moved[c] != 0 && moved[1 - c] == 0) ++alone_[c];
  if (moved[0] == 0 || moved[1] == 0) return;
  ((moved[0] > 0) == (moved[1] > 0) ? same_ : opposite_) += 1;
}

bool MotionDirectionCheck::mirrored() const {
  return opposite_ >= kMotionMinOppositeFrames &&
         static_cast<double>(opposite_) >= kMotionOppositeShare * static_cast<double>(same_ + opposite_);
}

int MotionDirectionCheck::still_camera() const {
  for (int c = 0; c < 2; ++c)
    if (alone_[1 - c] >= kMotionMinOppositeFrames &&
        static_cast<double>(alone_[1 - c]) >= kMotionOppositeShare * static_cast<double>(moved()))
      return c;
  return -1;
}

std::string still_camera_text(int still, size_t alone, size_t counted, const std::string& root) {
  const std::string s = "cam" + std::to_string(still), m = "cam" + std::to_string(1 - still);
  return s + "'s images did not move on " + std::to_string(alone) + " of the " + std::to_string(counted) +
         " frames where either camera's moved a working column or more, while " + m +
         "'s did: the two cameras look the same way (T_BS), so the rig's motion moves both images. " + s +
         " sees nothing that moves (its lens covered or blocked by something plain) or delivers the same frame "
         "again and again (" + shown_path(root) + "/" + s + "/); V is not observable from one camera";
}

std::string opposite_motion_text(size_t opposite, size_t counted, const std::string& root) {
  return "cam0's and cam1's images moved opposite ways on " + std::to_string(opposite) + " of the " +
         std::to_string(counted) +
         " frames where both moved a working column or more. The cameras look the same way (T_BS), so any motion "
         "of the rig moves both images the same way: the images of one camera are mirrored left-right, or upside "
         "down where its T_BS says upright (" + shown_path(root) + "/cam0/sensor.yaml, cam1/sensor.yaml)";
}

}  // namespace lumavel::host
