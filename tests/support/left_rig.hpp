// The geometry shared by the tests' synthetic rigs (synthetic_rig.hpp, the
// soak's pillar scene): two upright pinhole cameras looking left (body +y),
// cam1 ahead of cam0 by `baseline`, cam1 yawed by `misalignment` against cam0
// (each camera half of it off body +y), image u along body +x (u_sign -1).
#pragma once
#include <cmath>

#include "lumavel/host/settings.hpp"

namespace lumavel::test {

constexpr double kLeftRigPi = 3.14159265358979323846;

inline double left_rig_fu(int width, double hfov) { return width / 2.0 / std::tan(hfov / 2); }
inline double left_rig_axis(int cam, double misalignment) {
  return kLeftRigPi / 2 + (cam == 1 ? misalignment / 2 : -misalignment / 2);
}

// Settings of both engines for such a rig (default configuration otherwise).
inline host::EstimatorSettings left_rig_settings(int width, int height, double hfov, double baseline,
                                                 double misalignment) {
  host::EstimatorSettings s;
  s.width = width;
  s.height = height;
  for (int i = 0; i < 2; ++i) {
    s.cam[i].fu = left_rig_fu(width, hfov);
    s.cam[i].cu = (width - 1) / 2.0;
    s.cam[i].axis_yaw = left_rig_axis(i, misalignment);
    s.cam[i].u_sign = -1;
  }
  s.baseline = baseline;
  s.kernels = host::default_kernels(hfov);
  s.normaliser = {0, hfov / 2 / 3};
  return s;
}

}  // namespace lumavel::test
