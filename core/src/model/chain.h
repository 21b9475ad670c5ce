// SPDX-License-Identifier: Apache-2.0
// A serial kinematic chain as the model computes with it: fixed joint placements, joint axes,
// link inertias and the flange. Built from a URDF (urdf_loader.h) or from a DH table (below).
#pragma once

#include <array>
#include <string>

#include <Eigen/Geometry>

#include "model/robot_spec.h"

namespace xmate::model {

struct ChainJoint {
  std::string name;
  // Parent link frame -> this joint's frame at q = 0 (URDF <origin>).
  Eigen::Isometry3d origin = Eigen::Isometry3d::Identity();
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();  // unit, in the joint frame (URDF <axis>)
  double lower = 0, upper = 0;  // rad
  double velocity = 0;          // rad/s
  double effort = 0;            // Nm
};

struct ChainLink {
  std::string name;
  double mass = 0;                                         // kg
  Eigen::Vector3d com = Eigen::Vector3d::Zero();           // centre of mass in the link frame, m
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();       // about the centre of mass, link axes
  std::string mesh;                                        // visual mesh file, absolute path ("" if none)
  Eigen::Isometry3d visual_origin = Eigen::Isometry3d::Identity();
  Eigen::Vector3d mesh_scale = Eigen::Vector3d::Ones();
};

struct Chain {
  std::string name;  // robot name as in the URDF
  int dof = 0;       // 6 or 7
  ChainLink base;    // fixed to the world; frame = robot base frame
  // joints[i] moves links[i]; entries at index >= dof are unused.
  std::array<ChainJoint, 7> joints;
  std::array<ChainLink, 7> links;
  // Last link frame -> flange frame (a fixed joint in the URDF).
  Eigen::Isometry3d flange = Eigen::Isometry3d::Identity();
};

// The chain of a DH table alone: link i's frame sits on joint i's axis (frame i-1 of the DH
// convention, turned by theta_i + axis_sign_i * q_i), so joint i+1's origin is Tz(d_i) Tx(a_i)
// Rx(alpha_i) Rz(theta_i+1) and its axis is axis_sign_i+1 * z. No inertias.
// This is the same frame convention the URDF generator writes. Any thread; allocates (names), not
// for the real-time loop.
Chain chainFromDh(const RobotSpec& spec);

// The DH convention's flange pose, computed directly from the table (reference for tests and the
// chain check of makeArmModel). Any thread; not for the real-time loop (Eigen transforms, no allocation).
Eigen::Isometry3d dhFlangePose(const RobotSpec& spec, const std::array<double, 7>& q);

}  // namespace xmate::model
