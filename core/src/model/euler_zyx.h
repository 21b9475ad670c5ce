// SPDX-License-Identifier: Apache-2.0
// KUKA's orientation angles A B C: R = Rz(A) Ry(B) Rx(C) (Z-Y-X Euler angles, radians here; the RSI
// wire carries degrees). Used for DEF_RIst / DEF_RSol and POSCORR corrections (docs/rsi.md, "Units").
#pragma once

#include <cmath>

#include <Eigen/Geometry>

namespace xmate::model {

struct AbcAngles {
  double a = 0, b = 0, c = 0;  // rad: about z, then the new y, then the new x
};

inline Eigen::Matrix3d rotationFromAbc(const AbcAngles& abc) {
  return (Eigen::AngleAxisd(abc.a, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(abc.b, Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(abc.c, Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

// B in [-pi/2, pi/2]. At B = +-pi/2 (gimbal lock) only A -+ C is defined: C is set to 0.
inline AbcAngles abcFromRotation(const Eigen::Matrix3d& r) {
  AbcAngles abc;
  const double cos_b = std::hypot(r(0, 0), r(1, 0));
  abc.b = std::atan2(-r(2, 0), cos_b);
  if (cos_b > 1e-12) {
    abc.a = std::atan2(r(1, 0), r(0, 0));
    abc.c = std::atan2(r(2, 1), r(2, 2));
  } else {
    abc.a = std::atan2(-r(0, 1), r(1, 1));
    abc.c = 0;
  }
  return abc;
}

}  // namespace xmate::model
