// SPDX-License-Identifier: Apache-2.0
// Forward kinematics and geometric Jacobian: one pass down the chain with 3x3 rotations and
// translations (joint rotations about +z or -z take the fast path of jointRotation()).
#include "model/kinematics.h"

namespace xmate::model {
namespace {

// Link frames as rotation + position in the base frame, the working form of this file.
struct LinkPoints {
  std::array<Eigen::Matrix3d, kMaxDof> rotation;
  std::array<Eigen::Vector3d, kMaxDof> position;
};

void computeLinkPoints(const ArmModel& arm, const JointVector& q, LinkPoints& out) {
  Eigen::Matrix3d r = Eigen::Matrix3d::Identity();
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
  for (int i = 0; i < arm.dof; ++i) {
    const JointPlacement& joint = arm.joints[i];
    p += r * joint.translation;
    r = r * jointRotation(joint, q[i]);
    out.rotation[i] = r;
    out.position[i] = p;
  }
}

Eigen::Isometry3d makePose(const Eigen::Matrix3d& r, const Eigen::Vector3d& p) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.linear() = r;
  t.translation() = p;
  return t;
}

// Frame `offset` (given relative to the frame (r, p)) in the base frame.
Eigen::Isometry3d attach(const Eigen::Matrix3d& r, const Eigen::Vector3d& p, const Eigen::Isometry3d& offset) {
  return makePose(r * offset.linear(), p + r * offset.translation());
}

}  // namespace

void forwardKinematics(const ArmModel& arm, const JointVector& q, LinkFrames& out) {
  LinkPoints points;
  computeLinkPoints(arm, q, points);
  for (int i = 0; i < arm.dof; ++i) out.links[i] = makePose(points.rotation[i], points.position[i]);
  const int last = arm.dof - 1;
  out.flange = attach(points.rotation[last], points.position[last], arm.flange);
  out.tcp = out.flange * arm.tool;
}

Eigen::Isometry3d flangePose(const ArmModel& arm, const JointVector& q) {
  LinkPoints points;
  computeLinkPoints(arm, q, points);
  const int last = arm.dof - 1;
  return attach(points.rotation[last], points.position[last], arm.flange);
}

Eigen::Isometry3d tcpPose(const ArmModel& arm, const JointVector& q) { return flangePose(arm, q) * arm.tool; }

Jacobian tcpJacobian(const ArmModel& arm, const JointVector& q) {
  LinkPoints points;
  computeLinkPoints(arm, q, points);
  const int last = arm.dof - 1;
  const Eigen::Isometry3d tcp = attach(points.rotation[last], points.position[last], arm.flange) * arm.tool;
  const Eigen::Vector3d p_tcp = tcp.translation();
  Jacobian jac = Jacobian::Zero();
  for (int i = 0; i < arm.dof; ++i) {
    const Eigen::Vector3d z = arm.joints[i].axis_is_z ? Eigen::Vector3d(arm.joints[i].z_sign * points.rotation[i].col(2))
                                                       : Eigen::Vector3d(points.rotation[i] * arm.joints[i].axis);
    jac.block<3, 1>(0, i) = z.cross(p_tcp - points.position[i]);
    jac.block<3, 1>(3, i) = z;
  }
  return jac;
}

JointVector wrenchToJointTorques(const ArmModel& arm, const JointVector& q, const Vector6d& wrench) {
  return tcpJacobian(arm, q).transpose() * wrench;
}

}  // namespace xmate::model
