// SPDX-License-Identifier: Apache-2.0
// 6-axis inverse kinematics. With the xMate 3/7 DH tables the flange orientation factors as
//   R = [Rz(q1) Ry(q2 + q3)] [Rz(q4) Ry(q5) Rz(q6)],
// the shoulder S sits at (0, 0, d1), and the wrist centre is
//   S + Rz(q1) Ry(q2) (a2 + d4 sin q3, 0, d4 cos q3).
#include "model/ik_six_axis.h"

#include <algorithm>
#include <cmath>

#include "model/euler_zyz.h"

namespace xmate::model {
namespace {

constexpr double kPi = 3.14159265358979323846;

}  // namespace

IkStatus sixAxisCandidates(const ArmModel& arm, const Eigen::Isometry3d& flange, const JointVector& q_init,
                           IkCandidates& out) {
  const ArmGeometry& g = arm.geometry;
  const Eigen::Matrix3d& r = flange.linear();
  const Eigen::Vector3d sw = shoulderToWrist(g, flange);
  const double reach = sw.norm();
  const double a2 = g.upper_arm, d4 = g.forearm;

  if (reach > a2 + d4 + kIkReachTolerance) return IkStatus::kBeyondReach;
  if (reach < std::abs(a2 - d4) - kIkReachTolerance) return IkStatus::kTooClose;
  const double s3 = std::clamp((reach * reach - a2 * a2 - d4 * d4) / (2 * a2 * d4), -1.0, 1.0);
  if (std::acos(s3) < kIkSingularTolerance || std::acos(-s3) < kIkSingularTolerance)
    return IkStatus::kSingular;  // stretched or folded
  const double horizontal = std::hypot(sw.x(), sw.y());
  if (horizontal < kIkSingularTolerance) return IkStatus::kSingular;  // on the J1 axis

  const double elbow_up = std::asin(s3);
  const double azimuth = std::atan2(sw.y(), sw.x());
  for (int shoulder = 0; shoulder < 2; ++shoulder) {  // facing the wrist or turned away from it
    const double q1 = azimuth + shoulder * kPi;
    const double x = shoulder == 0 ? horizontal : -horizontal;  // sw in the plane of the arm
    for (const double q3 : {elbow_up, kPi - elbow_up}) {
      const double along = a2 + d4 * std::sin(q3), across = d4 * std::cos(q3);
      JointVector q = JointVector::Zero();
      q[0] = q1;
      q[1] = std::atan2(across, along) - std::atan2(sw.z(), x);
      q[2] = q3;
      bool wrist_singular = false;  // J4/J6 coaxial
      const Eigen::Matrix3d forearm = rotZ(q[0]) * rotY(q[1] + q[2]);
      const ZyzAngles w = zyzForIk(forearm.transpose() * r, q_init[3], wrist_singular);
      addWristBranches(out, q, 3, w, wrist_singular);  // sign of q5
    }
  }
  return IkStatus::kOk;
}

}  // namespace xmate::model
