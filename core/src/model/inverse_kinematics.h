// SPDX-License-Identifier: Apache-2.0
// Closed-form inverse kinematics of an ArmModel: TCP pose (+ arm angle psi on 7-axis arms) ->
// joint angles, nearest a given configuration, with the vendor's result codes. The arm angle of
// a configuration comes from armAngle(). Definitions and branches: docs/kinematics.md.
// Real-time safe: no allocation, no exceptions on the solving path.
#pragma once

#include <array>

#include <Eigen/Core>

#include "model/arm_model.h"

namespace xmate::model {

// Same values as xmate::XmateModel::IkResult (model.h).
enum class IkStatus : int {
  kOk = 0,
  kBeyondReach = -1,        // wrist centre farther from the shoulder than the stretched arm
  kTooClose = -2,           // wrist centre closer than the elbow joint's range can fold
  kInvalidPose = -3,        // pose not a rigid transform, or NaN/Inf in q_init or psi
  kArmJointTooFast = -4,    // an arm joint (J1..J4; 6-axis J1..J3) would exceed its rated speed
  kWristJointTooFast = -5,  // only wrist joints would exceed their rated speed
  kAboveSoftLimit = -6,     // every solution breaks a soft limit; the nearest first breaks an upper one
  kBelowSoftLimit = -7,     // ... a lower one
  kSingular = -8,           // the chosen solution is within kIkSingularTolerance of a singularity
};

// Distance from a singularity below which the IK reports kSingular (measures: docs/kinematics.md).
inline constexpr double kIkSingularTolerance = 1e-6;
// Distance (m) beyond the stretched arm's reach still treated as "stretched" rather than "beyond".
inline constexpr double kIkReachTolerance = 1e-9;

// One-line English description of a status, for messages and logs.
const char* ikStatusText(IkStatus status);

// True if pose is a rigid transform: finite, last row 0 0 0 1 (within 1e-6), rotation orthonormal
// within 1e-6 with determinant +1.
bool isRigidTransform(const Eigen::Matrix4d& pose);

// Joint angles that put the TCP (the flange when no tool is set) at tcp_pose with arm angle psi
// (ignored on 6-axis arms): among the up to 8 branch solutions, the one nearest q_init (Euclidean,
// each joint moved by a multiple of 2*pi where its range allows) within the soft limits; then the
// rated-speed check against q_init. q_out is written only when the result is kOk. Works for every
// family (xMate 7-axis, xMate 6-axis, KUKA offset wrist). Any thread; real-time safe.
IkStatus inverseKinematics(const ArmModel& arm, const Eigen::Matrix4d& tcp_pose, double psi,
                           const JointVector& q_init, JointVector& q_out);

// One branch of inverseKinematicsBranches.
struct IkBranchSolution {
  JointVector q = JointVector::Zero();  // each joint moved by the 2*pi multiple nearest q_init that
                                        // keeps it inside its soft limits (if there is one)
  bool within_limits = false;           // every joint inside the soft limits
  bool singular = false;                // within kIkSingularTolerance of a singularity
};
struct IkBranchSolutions {
  std::array<IkBranchSolution, 8> items;
  int count = 0;
};

// Every branch solution for tcp_pose (and psi on 7-axis arms), before the choice inverseKinematics
// makes: up to 8 (6-axis: shoulder front/back x elbow up/down x wrist flip). q_init only picks the
// 2*pi representatives and the split at a wrist singularity. Returns kInvalidPose, kBeyondReach,
// kTooClose or kSingular (when no branch can be computed) like inverseKinematics, else kOk with
// out.count >= 1. No rated-speed check. Any thread; real-time safe.
IkStatus inverseKinematicsBranches(const ArmModel& arm, const Eigen::Matrix4d& tcp_pose, double psi,
                                   const JointVector& q_init, IkBranchSolutions& out);

// Arm angle psi of configuration q of a 7-axis arm (0 on 6-axis arms): inverseKinematics(
// tcpPose(q), armAngle(q), q) gives back q. Any thread; real-time safe.
double armAngle(const ArmModel& arm, const JointVector& q);

}  // namespace xmate::model
