// SPDX-License-Identifier: Apache-2.0
// Forward kinematics (every link frame, flange, TCP) and the geometric Jacobian of an ArmModel.
// Real-time safe: no allocation, fixed-size Eigen types only.
#pragma once

#include <array>

#include <Eigen/Geometry>

#include "model/arm_model.h"

namespace xmate::model {

// Poses in the robot base frame.
struct LinkFrames {
  std::array<Eigen::Isometry3d, kMaxDof> links;  // link i's frame (on joint i's axis); unused >= dof
  Eigen::Isometry3d flange;
  Eigen::Isometry3d tcp;  // flange * tool
};

// All link frames, the flange and the TCP at joint angles q.
void forwardKinematics(const ArmModel& arm, const JointVector& q, LinkFrames& out);

// The flange pose alone (ignores the tool).
Eigen::Isometry3d flangePose(const ArmModel& arm, const JointVector& q);

// The TCP pose: flange * tool (the flange when no tool is set).
Eigen::Isometry3d tcpPose(const ArmModel& arm, const JointVector& q);

// Geometric Jacobian of the TCP point: twist [v; omega] = J dq, v of the TCP origin, both in the
// base frame. Columns >= dof are zero. (KDL's ChainJntToJacSolver uses the same convention for
// the chain's last frame.)
Jacobian tcpJacobian(const ArmModel& arm, const JointVector& q);

// Joint torques equivalent to a wrench [force; moment] applied to the TCP (base frame, moment about
// the TCP): tau_ext = J^T F. The simulator uses it to turn an external push into joint torques.
JointVector wrenchToJointTorques(const ArmModel& arm, const JointVector& q, const Vector6d& wrench);

}  // namespace xmate::model
