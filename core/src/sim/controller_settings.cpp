// SPDX-License-Identifier: Apache-2.0
// Default settings of a freshly booted simulated controller (see controller_settings.h).
#include "sim/controller_settings.h"

#include "sim/pose_math.h"

namespace xmate::sim {

ControllerSettings defaultSettings(const model::RobotSpec& spec) {
  ControllerSettings s;
  // Collision thresholds default to the maxima setCollisionBehavior accepts (the manual's table).
  s.collision_thresholds = toJointVector(spec.collision_threshold_max, spec.dof);
  // Stiffest joint and Cartesian impedance the controller accepts.
  s.joint_stiffness = toJointVector(spec.joint_stiffness_max, spec.dof);
  s.cartesian_stiffness = toVector6(model::kCartesianStiffnessMax);
  s.desired_wrench = Vector6d::Zero();
  s.soft_lower = toJointVector(spec.q_min, spec.dof);
  s.soft_upper = toJointVector(spec.q_max, spec.dof);
  return s;
}

}  // namespace xmate::sim
