// SPDX-License-Identifier: Apache-2.0
// 7-axis S-R-S inverse kinematics. With the xMate Pro DH tables the flange orientation factors as
//   R = [Rz(q1) Ry(q2) Rz(q3)] Ry(q4) [Rz(q5) Ry(q6) Rz(q7)] = Q Ry(q4) W,
// the shoulder S sits at (0, 0, d1), and the wrist centre is S + Q (d5 sin q4, 0, d3 + d5 cos q4).
// The reference shoulder Q0 is the one with q3 = 0 and joint 1 facing the wrist; the arm angle
// psi rotates it about the shoulder-wrist line: Q = Rot(u, psi) Q0 (docs/kinematics.md).
#include "model/ik_srs.h"

#include <algorithm>
#include <cmath>

#include "model/euler_zyz.h"

namespace xmate::model {
namespace {

// Shoulder-to-wrist vector in the shoulder frame Q for elbow angle q4.
Eigen::Vector3d upperAndForearm(const ArmGeometry& g, double q4) {
  return {g.forearm * std::sin(q4), 0.0, g.upper_arm + g.forearm * std::cos(q4)};
}

// The reference shoulder rotation (q3 = 0, joint 1 facing the wrist) for shoulder-wrist vector sw.
Eigen::Matrix3d referenceShoulder(const ArmGeometry& g, const Eigen::Vector3d& sw, double q4) {
  const Eigen::Vector3d v = upperAndForearm(g, q4);
  const double q1 = std::atan2(sw.y(), sw.x());
  const double polar = std::atan2(std::hypot(sw.x(), sw.y()), sw.z());  // sw's angle from vertical
  const double q2 = polar - std::atan2(v.x(), v.z());
  return rotZ(q1) * rotY(q2);
}

}  // namespace

IkStatus srsCandidates(const ArmModel& arm, const Eigen::Isometry3d& flange, double psi, const JointVector& q_init,
                       IkCandidates& out) {
  const ArmGeometry& g = arm.geometry;
  const Eigen::Matrix3d& r = flange.linear();
  const Eigen::Vector3d sw = shoulderToWrist(g, flange);
  const double reach = sw.norm();
  const double d3 = g.upper_arm, d5 = g.forearm;

  if (reach > d3 + d5 + kIkReachTolerance) return IkStatus::kBeyondReach;
  const double c4 = std::clamp((reach * reach - d3 * d3 - d5 * d5) / (2 * d3 * d5), -1.0, 1.0);
  const double elbow = std::acos(c4);  // |q4|
  const double elbow_range = std::max(arm.hardware_upper[3], -arm.hardware_lower[3]);
  if (elbow > elbow_range) return IkStatus::kTooClose;
  if (elbow < kIkSingularTolerance) return IkStatus::kSingular;                          // stretched
  if (std::hypot(sw.x(), sw.y()) < kIkSingularTolerance) return IkStatus::kSingular;  // on the J1 axis

  const Eigen::Matrix3d rot_psi = Eigen::AngleAxisd(psi, sw / reach).toRotationMatrix();
  for (const double sign4 : {1.0, -1.0}) {
    JointVector q = JointVector::Zero();
    q[3] = sign4 * elbow;
    const Eigen::Matrix3d shoulder = rot_psi * referenceShoulder(g, sw, q[3]);
    bool shoulder_singular = false, wrist_singular = false;  // J1/J3 or J5/J7 coaxial
    const ZyzAngles s = zyzForIk(shoulder, q_init[0], shoulder_singular);
    const ZyzAngles w = zyzForIk((shoulder * rotY(q[3])).transpose() * r, q_init[4], wrist_singular);
    for (int branch = 0; branch < 2; ++branch) {  // sign of q2
      setZyzBranch(q, 0, s, branch);
      addWristBranches(out, q, 4, w, shoulder_singular || wrist_singular);  // sign of q6
    }
  }
  return IkStatus::kOk;
}

double srsArmAngle(const ArmModel& arm, const JointVector& q) {
  const ArmGeometry& g = arm.geometry;
  const Eigen::Matrix3d shoulder = rotZ(q[0]) * rotY(q[1]) * rotZ(q[2]);
  const Eigen::Vector3d sw = shoulder * upperAndForearm(g, q[3]);
  const Eigen::Vector3d u = sw.normalized();
  const Eigen::Matrix3d rot_psi = shoulder * referenceShoulder(g, sw, q[3]).transpose();
  // rot_psi turns about u: sin(psi) = u . vee(R - R^T) / 2, cos(psi) = (trace R - 1) / 2.
  const Eigen::Vector3d vee(rot_psi(2, 1) - rot_psi(1, 2), rot_psi(0, 2) - rot_psi(2, 0),
                            rot_psi(1, 0) - rot_psi(0, 1));
  return std::atan2(0.5 * u.dot(vee), 0.5 * (rot_psi.trace() - 1.0));
}

}  // namespace xmate::model
