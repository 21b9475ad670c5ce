// SPDX-License-Identifier: Apache-2.0
// The published facts about each xMate model (docs/robot_models.md), in SI units, in one place.
// Everything else -- the URDF generator, the model, the planners, the simulator, the GUI's
// editors -- reads limits and geometry from here.
#pragma once

#include <array>
#include <string_view>

#include <xmate/types.h>

namespace xmate::model {

// One row of a standard (distal) Denavit-Hartenberg table:
// T(i-1 -> i) = Rz(theta + q_i) * Tz(d) * Tx(a) * Rx(alpha).
struct DhRow {
  double a;      // m
  double alpha;  // rad
  double d;      // m
  double theta;  // rad (all zero for the xMate models)
};

struct RobotSpec {
  XmateType type;
  std::string_view name;          // file stem: "xmate7_pro" -> resources/robots/xmate7_pro.urdf
  std::string_view display_name;  // "xMate Pro 7"
  int dof;                        // 6 or 7; arrays below are 7 long, unused entries are 0
  std::array<DhRow, 7> dh;
  std::array<double, 7> q_max;         // rad (hardware limit)
  std::array<double, 7> q_min;         // rad
  std::array<double, 7> dq_max;        // rad/s
  std::array<double, 7> ddq_max;       // rad/s^2
  std::array<double, 7> jerk_max;      // rad/s^3
  std::array<double, 7> tau_max;       // Nm
  std::array<double, 7> dtau_max;      // Nm/s
  std::array<double, 7> collision_threshold_max;  // Nm, setCollisionBehavior upper bound
  std::array<double, 7> joint_stiffness_max;      // Nm/rad, setJointImpedance upper bound
  // Link masses in kg, ESTIMATES from public robot descriptions (docs/robot_models.md, "Link
  // masses"): base, link 1..dof.
  // A base mass of 0 means "not published"; the generator then derives one from the base geometry.
  std::array<double, 8> link_mass;
};

// Cartesian limits (the source manual's table is empty; choice documented in docs/planning.md).
struct CartesianLimits {
  double v_trans, a_trans, j_trans;  // m/s, m/s^2, m/s^3
  double v_rot, a_rot, j_rot;        // rad/s, rad/s^2, rad/s^3
  double v_elbow, a_elbow, j_elbow;  // arm angle: rad/s, rad/s^2, rad/s^3
};

// Limits the planners stay within (the published manual values).
const CartesianLimits& plannerCartesianLimits();
// Limits the controller (and our simulator) enforces: the vendor rate limiter's constants
// (docs/robot_models.md, "Cartesian limits"), at or above the planner's so a correct plan never trips them.
const CartesianLimits& controllerCartesianLimits();

// Cartesian stiffness upper bounds of setCartesianImpedance: 3000 N/m x3, 300 Nm/rad x3.
inline constexpr std::array<double, 6> kCartesianStiffnessMax{3000, 3000, 3000, 300, 300, 300};

const RobotSpec& robotSpec(XmateType type);
// Looks a model up by its file stem ("xmate7_pro"); returns nullptr if unknown.
const RobotSpec* findRobotSpec(std::string_view name);
// All four models, in XmateType order.
const std::array<XmateType, 4>& allRobotTypes();

}  // namespace xmate::model
