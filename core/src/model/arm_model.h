// SPDX-License-Identifier: Apache-2.0
// The arm as kinematics, inverse kinematics and dynamics compute with it: a Chain flattened into
// fixed-size arrays (joint placements, axes, link inertias) plus the user's tool, payload and limits.
#pragma once

#include <array>
#include <cmath>

#include <Eigen/Geometry>

#include "model/chain.h"
#include "model/robot_spec.h"

namespace xmate::model {

inline constexpr int kMaxDof = 7;

// Joint-space quantities. Entries at index >= dof are zero and ignored.
using JointVector = Eigen::Matrix<double, kMaxDof, 1>;
// Joint-space matrices (mass matrix). Rows and columns >= dof are zero.
using JointMatrix = Eigen::Matrix<double, kMaxDof, kMaxDof>;
// Geometric Jacobian: rows [v; omega] in the base frame, one column per joint (columns >= dof zero).
using Jacobian = Eigen::Matrix<double, 6, kMaxDof>;
// A wrench [force; moment] or twist [v; omega].
using Vector6d = Eigen::Matrix<double, 6, 1>;

// Standard gravity; the base frame's z axis points up, so gravity is (0, 0, -kStandardGravity).
inline constexpr double kStandardGravity = 9.81;
inline Eigen::Vector3d standardGravity() { return {0.0, 0.0, -kStandardGravity}; }

// Where a joint sits on its parent link and how it turns.
struct JointPlacement {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();  // parent link -> joint frame at q = 0
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();   // joint origin in the parent link frame
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();         // unit axis in the joint (= child link) frame
  bool axis_is_z = true;                                   // fast path: axis is exactly +z or -z
  double z_sign = 1;                                       // with axis_is_z: +1 for +z, -1 for -z
};

// Mass properties of a rigid body about its link frame's origin (the form RNEA and CRBA use).
struct LinkInertia {
  double mass = 0;                                               // kg
  Eigen::Vector3d first_moment = Eigen::Vector3d::Zero();        // mass * centre of mass, kg m
  Eigen::Matrix3d rotational = Eigen::Matrix3d::Zero();          // about the link origin, kg m^2
};

// A payload as SetLoad describes it: everything in the flange frame.
struct Payload {
  double mass = 0;                                      // kg
  Eigen::Vector3d com = Eigen::Vector3d::Zero();        // centre of mass, m
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();    // about the centre of mass, kg m^2
};

// Which closed-form IK fits the arm's DH table (docs/kinematics.md).
enum class IkGeometry {
  kSrs,          // 7-axis S-R-S (xMate Pro 3/7)
  kSixAxis,      // 6-axis, shoulder on the J1 axis, no elbow offset, spherical wrist (xMate 3/7)
  kOffsetWrist,  // 6-axis ortho-parallel arm with shoulder and elbow offsets, spherical wrist (KUKA)
};

// The lengths the closed-form IK works with, from the model's DH table (docs/kinematics.md).
//  7-axis S-R-S:             shoulder at (0, 0, base_to_shoulder); upper arm d3, forearm d5, flange d7.
//  6-axis spherical wrist:   shoulder at (0, 0, base_to_shoulder); upper arm a2, forearm d4, flange d6.
//  offset wrist (KUKA):      shoulder a1 out from the J1 axis at height d1; upper arm a2; the
//                            forearm leaves the elbow axis sideways by a3 (signed), then runs d4
//                            along the A4 axis to the wrist centre; flange d6 beyond it.
struct ArmGeometry {
  double base_to_shoulder = 0;   // d_bs = d1
  double upper_arm = 0;          // d_se = d3 (7-axis) or a2 (6-axis)
  double forearm = 0;            // d_ew = d5 (7-axis) or d4 (6-axis)
  double wrist_to_flange = 0;    // d_wf = d7 (7-axis) or d6 (6-axis)
  IkGeometry kind = IkGeometry::kSixAxis;
  double shoulder_offset = 0;    // offset wrist: a1, from the J1 axis to the J2 axis, m
  double elbow_offset = 0;       // offset wrist: a3, from the J3 axis to the J4 axis (signed), m
  std::array<DhRow, 6> dh{};     // offset wrist: the DH rows (angle offsets, axis signs, alphas)
};

struct ArmModel {
  int dof = 0;                // 6 or 7
  int arm_joint_count = 0;    // joints before the wrist: 4 (7-axis) or 3 (6-axis)
  RobotFamily family = RobotFamily::kXmate;
  std::array<JointPlacement, kMaxDof> joints;
  std::array<LinkInertia, kMaxDof> chain_links;  // as described by the chain (URDF)
  std::array<LinkInertia, kMaxDof> links;        // chain_links with the payload added to the last link
  Eigen::Isometry3d flange = Eigen::Isometry3d::Identity();        // last link -> flange
  Eigen::Isometry3d tool = Eigen::Isometry3d::Identity();          // flange -> TCP (SetCoor)
  Eigen::Isometry3d tool_inverse = Eigen::Isometry3d::Identity();  // TCP -> flange
  Payload payload;
  ArmGeometry geometry;
  JointVector hardware_lower = JointVector::Zero(), hardware_upper = JointVector::Zero();  // rad
  JointVector lower = JointVector::Zero(), upper = JointVector::Zero();  // soft limits used by IK, rad
  JointVector max_velocity = JointVector::Zero();                        // rated speed, rad/s
  double speed_check_interval = 0.001;  // s; IK codes -4/-5 (0 = off)
};

// Builds the model of `spec` (any family) from its chain (URDF or chainFromDh). Throws
// std::runtime_error if the chain's joint count differs from the spec's or if its flange pose does
// not follow the spec's DH table (the closed-form IK relies on that geometry). Any thread; allocates,
// not for the real-time loop.
ArmModel makeArmModel(const Chain& chain, const RobotSpec& spec);

// Tool centre point relative to the flange. Throws std::invalid_argument unless it is a rigid transform.
void setTool(ArmModel& arm, const Eigen::Isometry3d& flange_to_tcp);

// True when `inertia` is finite and symmetric to 1e-9 relative to its largest entry: the one
// symmetry test of a payload inertia for setPayload, the client and the simulator (parameter_checks).
bool isSymmetricInertia(const Eigen::Matrix3d& inertia);

// Payload attached to the flange. Throws std::invalid_argument for a negative or non-finite mass, a
// non-finite centre of mass or an inertia that fails isSymmetricInertia; stores the inertia with its
// two triangles averaged, so the dynamics see an exactly symmetric matrix.
void setPayload(ArmModel& arm, const Payload& payload);

// Soft joint limits for the IK (rad). Throws std::invalid_argument unless
// hardware_lower <= lower < upper <= hardware_upper for every joint of the arm.
void setSoftLimits(ArmModel& arm, const JointVector& lower, const JointVector& upper);

// Interval of the IK's rated-speed check (s); 0 turns it off. Throws std::invalid_argument if negative.
void setSpeedCheckInterval(ArmModel& arm, double seconds);

// Mass properties of a body (mass, centre of mass and inertia about it, all in frame B) about the
// origin of frame A, where a_T_b places B in A.
LinkInertia inertiaAboutOrigin(double mass, const Eigen::Vector3d& com, const Eigen::Matrix3d& inertia_about_com,
                               const Eigen::Isometry3d& a_T_b = Eigen::Isometry3d::Identity());

// Rotation of joint i's child link relative to its parent link at angle q. Real-time safe.
inline Eigen::Matrix3d jointRotation(const JointPlacement& joint, double q) {
  if (joint.axis_is_z) {
    const double c = std::cos(q), s = joint.z_sign * std::sin(q);
    Eigen::Matrix3d r;
    r.col(0) = c * joint.rotation.col(0) + s * joint.rotation.col(1);
    r.col(1) = c * joint.rotation.col(1) - s * joint.rotation.col(0);
    r.col(2) = joint.rotation.col(2);
    return r;
  }
  return joint.rotation * Eigen::AngleAxisd(q, joint.axis).toRotationMatrix();
}

}  // namespace xmate::model
