// SPDX-License-Identifier: Apache-2.0
// Everything the TCP commands configure on the simulated controller (setCollisionBehavior,
// setJointImpedance, setFilters, ...), as one plain struct with the defaults a freshly booted
// controller has. Defaults and their reasons: docs/simulator_controller.md, in each setting's
// section ("Commands and filters", "Collision detection and the payload", ...).
#pragma once

#include <Eigen/Geometry>

#include "model/arm_model.h"
#include "model/robot_spec.h"

namespace xmate::sim {

using model::JointVector;
using model::Vector6d;

struct SafetyBox {
  bool active = false;
  Eigen::Vector3d size = Eigen::Vector3d::Zero();            // full edge lengths, m
  Eigen::Isometry3d frame = Eigen::Isometry3d::Identity();   // box centre and axes in the base frame
};

struct ControllerSettings {
  JointVector collision_thresholds;  // Nm, |estimated external joint torque| above -> collision
  JointVector joint_stiffness;       // Nm/rad, joint impedance mode
  Vector6d cartesian_stiffness;      // N/m x3, Nm/rad x3, Cartesian impedance mode
  Vector6d desired_wrench;           // N, Nm in the force-control frame (setCartImpDesiredTau)
  double joint_filter_hz = 100;      // cut-off of the joint position command filter
  double cartesian_filter_hz = 100;  // Cartesian pose command filter
  double torque_filter_hz = 100;     // torque command filter (torque mode)
  double measured_torque_filter_hz = 50;  // tau_m_filtered, motor_tau_filtered
  Eigen::Isometry3d force_frame = Eigen::Isometry3d::Identity();  // setFcCoor
  int force_frame_type = 0;          // wire numbering: 0 world, 1 tool, 2 path
  SafetyBox safety_box;
  JointVector soft_lower, soft_upper;  // rad (setJointLimit takes degrees)
  bool auto_limit = false;
  bool virtual_guide_enabled = false;  // stored only (EnableVirtualGuide)
  Vector6d virtual_guide_stiffness = Vector6d::Zero();
  Eigen::Isometry3d tool = Eigen::Isometry3d::Identity();  // flange -> TCP (setCoor)
  model::Payload load;                                      // setLoad
};

// The settings right after power-up / reboot for this model.
ControllerSettings defaultSettings(const model::RobotSpec& spec);

}  // namespace xmate::sim
