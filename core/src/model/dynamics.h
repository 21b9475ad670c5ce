// SPDX-License-Identifier: Apache-2.0
// Rigid-body dynamics of an ArmModel without friction: inverse dynamics by recursive Newton-Euler
// (RNEA), the joint-space mass matrix by the composite-rigid-body algorithm (CRBA), and the split
// of the torque into inertial, Coriolis/centrifugal and gravity terms.
//
// Equation of motion: tau = M(q) ddq + C(q, dq) dq + g(q) (+ J^T F for an external wrench,
// see wrenchToJointTorques() in kinematics.h). The payload (setPayload) is part of the last link.
// Gravity is a vector in the base frame; standardGravity() = (0, 0, -9.81) m/s^2.
// Real-time safe: no allocation, fixed-size Eigen types only.
#pragma once

#include <Eigen/Core>

#include "model/arm_model.h"

namespace xmate::model {

// tau = RNEA(q, dq, ddq): the joint torques that produce acceleration ddq at velocity dq under
// `gravity` (pass Vector3d::Zero() for none).
JointVector inverseDynamics(const ArmModel& arm, const JointVector& q, const JointVector& dq,
                            const JointVector& ddq, const Eigen::Vector3d& gravity = standardGravity());

// M(q), symmetric positive definite in its top-left dof x dof block, zero elsewhere.
JointMatrix massMatrix(const ArmModel& arm, const JointVector& q);

// g(q): torques that hold the arm still against gravity.
JointVector gravityTorques(const ArmModel& arm, const JointVector& q,
                           const Eigen::Vector3d& gravity = standardGravity());

// C(q, dq) dq: Coriolis and centrifugal torques.
JointVector coriolisTorques(const ArmModel& arm, const JointVector& q, const JointVector& dq);

// The terms of GetTauNoFriction: full = inertial + coriolis + gravity, each computed on its own
// (inertial = M(q) ddq, coriolis = C(q, dq) dq, gravity = g(q), full = RNEA(q, dq, ddq)).
struct TorqueTerms {
  JointVector full, inertial, coriolis, gravity;
};
TorqueTerms torqueTerms(const ArmModel& arm, const JointVector& q, const JointVector& dq, const JointVector& ddq,
                        const Eigen::Vector3d& gravity = standardGravity());

}  // namespace xmate::model
