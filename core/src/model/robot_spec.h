// SPDX-License-Identifier: Apache-2.0
// The published facts about each robot model -- the four ROKAE xMates and the two KUKA arms
// (docs/robot_models.md) -- in SI units, in one place. Everything else -- the URDF generator, the model, the planners, the simulator, the GUI's
// editors -- reads limits and geometry from here.
#pragma once

#include <array>
#include <optional>
#include <span>
#include <string_view>

#include <xmate/types.h>

namespace xmate::model {

// One row of a standard (distal) Denavit-Hartenberg table:
// T(i-1 -> i) = Rz(theta + axis_sign * q_i) * Tz(d) * Tx(a) * Rx(alpha).
// axis_sign is the sense of the joint: +1 turns about +z of DH frame i-1 (every xMate joint), -1
// about -z (KUKA's A1, A4 and A6, whose positive direction is the other way round).
struct DhRow {
  double a;              // m
  double alpha;          // rad
  double d;              // m
  double theta;          // rad (all zero for the xMate models)
  double axis_sign = 1;  // +1 or -1
};

// Which maker's robot a spec describes; it decides how the robot is talked to (xMate: RCI; KUKA:
// RSI) and which parts of the spec apply.
enum class RobotFamily { kXmate, kKuka };

struct RobotSpec {
  // The vendor API's model enum. Meaningful only for family == kXmate: the public XmateType has no
  // value for other makers' robots, so a KUKA spec holds XMATE7_PRO here as a filler that means
  // nothing. Read it through xmateType(spec), which says "none" for those.
  XmateType type;
  std::string_view name;          // file stem: "xmate7_pro" -> resources/robots/xmate7_pro.urdf
  std::string_view display_name;  // "xMate Pro 7"
  int dof;                        // 6 or 7; arrays below are 7 long, unused entries are 0
  // Joint values are the controller's (xMate J1..J7, KUKA A1..A6) in radians; the DH table and its
  // axis signs turn them into the geometry.
  std::array<DhRow, 7> dh;
  std::array<double, 7> q_max;         // rad (hardware limit)
  std::array<double, 7> q_min;         // rad
  std::array<double, 7> dq_max;        // rad/s
  std::array<double, 7> ddq_max;       // rad/s^2 (KUKA: chosen, not published)
  std::array<double, 7> jerk_max;      // rad/s^3 (KUKA: chosen, not published)
  std::array<double, 7> tau_max;       // Nm (KUKA: estimated, not published)
  std::array<double, 7> dtau_max;      // Nm/s (KUKA: chosen, not published)
  // Upper bounds of the xMate's setCollisionBehavior (Nm) and setJointImpedance (Nm/rad); all 0
  // for KUKA specs, which have no such settings (every value is refused).
  std::array<double, 7> collision_threshold_max;
  std::array<double, 7> joint_stiffness_max;
  // Link masses in kg, ESTIMATES (docs/robot_models.md, "Link masses"): base, link 1..dof. xMate:
  // from public robot descriptions; KUKA: the published robot weight split over the links.
  // A base mass of 0 means "not published"; the generator then derives one from the base geometry.
  std::array<double, 8> link_mass;
  RobotFamily family = RobotFamily::kXmate;
  double rated_payload_kg = 0;  // the largest load setLoad accepts
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

// All functions below return references to constant tables: any thread, real-time safe.

// The spec of an xMate model.
const RobotSpec& robotSpec(XmateType type);
// Looks a model of any family up by its file stem ("xmate7_pro", "kr6_r900_sixx", "kr16_2");
// returns nullptr if unknown. Check spec->family before using spec->type.
const RobotSpec* findRobotSpec(std::string_view name);
// The same, for callers that need an xMate (an XmateType): nullptr for unknown names and for
// models of other families.
const RobotSpec* findXmateSpec(std::string_view name);
// The four xMate models, in XmateType order.
const std::array<XmateType, 4>& allRobotTypes();
// Every model of every family: the four xMates in XmateType order, then KR 6 R900 sixx, KR 16-2.
std::span<const RobotSpec> allRobotSpecs();
// The spec's XmateType, or none for a model of another family.
std::optional<XmateType> xmateType(const RobotSpec& spec);

}  // namespace xmate::model
