// SPDX-License-Identifier: Apache-2.0
// Limit allowances: the joint limits and safety-box faces the simulated controller actually enforces.
// Inside the limits they are the limits; a joint (or the TCP) that starts a motion, hand guiding or
// power-on beyond them is allowed where it is, and the allowance narrows back as it returns, so
// there is always a way back (docs/simulator_controller.md, "There is always a way back").
// Allocation-free.
#pragma once

#include <Eigen/Geometry>

#include "model/arm_model.h"
#include "sim/controller_settings.h"

namespace xmate::sim {

using model::JointVector;

// How far beyond its current (or innermost) position an outside joint may still go, rad: covers
// the start tolerance of a first command and small servo errors.
inline constexpr double kJointAllowanceSlack = 0.005;
// The same for an outside TCP and the face of the safety box it is beyond, m.
inline constexpr double kBoxAllowanceSlack = 0.005;

// Per joint: the soft limit where the joint is inside it; q + slack (q - slack) for a joint beyond
// it, narrowed as the joint comes back, never below the soft limit.
struct JointAllowance {
  JointVector lower = JointVector::Zero();
  JointVector upper = JointVector::Zero();

  // Starts afresh at q (power-on, StartMove, StartDrag, new limits, a placed arm).
  void reset(const JointVector& q, const JointVector& soft_lower, const JointVector& soft_upper, int dof);
  // Every cycle: follows joints that moved back towards the limits; never widens.
  void ratchet(const JointVector& q, const JointVector& soft_lower, const JointVector& soft_upper, int dof);
};

// The same per face of the safety box, in the box's own frame (centre at 0, faces at +-size/2).
struct BoxAllowance {
  Eigen::Vector3d lower = Eigen::Vector3d::Zero();
  Eigen::Vector3d upper = Eigen::Vector3d::Zero();

  void reset(const SafetyBox& box, const Eigen::Vector3d& tcp_position);
  void ratchet(const SafetyBox& box, const Eigen::Vector3d& tcp_position);
  // True if the TCP (base frame) lies within the allowed faces (or on them).
  bool contains(const SafetyBox& box, const Eigen::Vector3d& tcp_position) const;
};

// The TCP position in the box's frame.
inline Eigen::Vector3d boxLocal(const SafetyBox& box, const Eigen::Vector3d& tcp_position) {
  return box.frame.inverse() * tcp_position;
}

}  // namespace xmate::sim
