// SPDX-License-Identifier: Apache-2.0
// Elementary rotations and the Z-Y-Z Euler decomposition the closed-form IK is built from: the
// xMate shoulders and wrists are Rz(a) Ry(b) Rz(c) (docs/kinematics.md, "Frames").
#pragma once

#include <cmath>

#include <Eigen/Core>

namespace xmate::model {

inline Eigen::Matrix3d rotZ(double a) {
  const double c = std::cos(a), s = std::sin(a);
  Eigen::Matrix3d r;
  r << c, -s, 0, s, c, 0, 0, 0, 1;
  return r;
}

inline Eigen::Matrix3d rotY(double b) {
  const double c = std::cos(b), s = std::sin(b);
  Eigen::Matrix3d r;
  r << c, 0, s, 0, 1, 0, -s, 0, c;
  return r;
}

// R = Rz(a) Ry(b) Rz(c) with b in [0, pi]. The other solution is (a + pi, -b, c + pi).
struct ZyzAngles {
  double a, b, c;
  double sin_b;  // >= 0; near 0 the split between a and c is undetermined
};

inline ZyzAngles zyzAngles(const Eigen::Matrix3d& r) {
  ZyzAngles z;
  z.sin_b = std::hypot(r(0, 2), r(1, 2));
  z.b = std::atan2(z.sin_b, r(2, 2));
  z.a = std::atan2(r(1, 2), r(0, 2));
  z.c = std::atan2(r(2, 1), -r(2, 0));
  return z;
}

// For sin(b) ~ 0 only a + c (b ~ 0) or a - c (b ~ pi) is defined: keep a = a_preferred, solve c.
inline void resolveDegenerateZyz(const Eigen::Matrix3d& r, double a_preferred, ZyzAngles& z) {
  const double theta = std::atan2(-r(0, 1), r(1, 1));
  z.a = a_preferred;
  z.c = r(2, 2) > 0 ? theta - a_preferred : a_preferred - theta;
}

}  // namespace xmate::model
