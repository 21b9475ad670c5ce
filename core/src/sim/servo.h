// SPDX-License-Identifier: Apache-2.0
// The control laws of the simulated controller, evaluated at the servo rate (every sub-step):
// joint position (computed torque), joint impedance, Cartesian impedance (also used for hand
// guiding), and the compensation added in torque mode. Each returns the motor torque; the
// controller's own model (configured tool and load, rotor inertia, friction) is what they know of
// the arm. Gains: docs/simulator_controller.md, "Controller modes". Allocation-free.
#pragma once

#include <Eigen/Geometry>

#include "model/arm_model.h"
#include "sim/plant.h"

namespace xmate::sim {

using model::Jacobian;
using model::JointMatrix;
using model::JointVector;
using model::Vector6d;

// Joint position control: natural frequency and damping ratio of the tracking error.
inline constexpr double kPositionBandwidth = 150.0;  // rad/s (~24 Hz)
inline constexpr double kPositionDampingRatio = 1.0;

// The reference of one sub-step.
struct JointSetpoint {
  JointVector q, dq, ddq;
};

// Computed torque: tau = M (ddq_r + Kd (dq_r - dq) + Kp (q_r - q)) + bias + friction.
JointVector positionControlTorque(const FrozenDynamics& model, const PlantParams& params, const PlantState& measured,
                                  const JointSetpoint& ref);

// Damping of joint impedance: critical for stiffness K against the diagonal of M, plus a floor so
// that joints with K = 0 still come to rest.
JointVector jointImpedanceDamping(const FrozenDynamics& model, const JointVector& stiffness, int dof);

// tau = K (q_r - q) + D (dq_r - dq) + M ddq_r + bias + friction.
JointVector jointImpedanceTorque(const FrozenDynamics& model, const PlantParams& params, const PlantState& measured,
                                 const JointSetpoint& ref, const JointVector& stiffness, const JointVector& damping);

// Cartesian impedance at the TCP, per axis [x y z rx ry rz] in the base frame:
// F = K e + D (v_r - v) + wrench, tau = J^T F + nullspace term + bias + friction.
struct CartesianImpedance {
  Eigen::Isometry3d target = Eigen::Isometry3d::Identity();
  Vector6d target_twist = Vector6d::Zero();
  Vector6d stiffness = Vector6d::Zero();
  Vector6d damping = Vector6d::Zero();
  Vector6d wrench = Vector6d::Zero();       // feed-forward wrench at the TCP, base frame
  JointVector nullspace_q = JointVector::Zero();  // 7-axis: posture the redundant motion is pulled to
  double nullspace_stiffness = 0;            // Nm/rad
  double nullspace_damping = 0;              // Nm s/rad
  JointMatrix nullspace_projector = JointMatrix::Zero();  // N^T (computed per cycle)
};

// Per cycle: the operational-space inertia Lambda's diagonal and the dynamically consistent
// nullspace projector N^T = I - J^T Lambda J M^-1, at the cycle's start.
struct OperationalSpace {
  Vector6d inertia_diagonal = Vector6d::Zero();
  JointMatrix nullspace_projector = JointMatrix::Zero();
};
OperationalSpace operationalSpace(const FrozenDynamics& model, const Jacobian& jacobian);

// Critical damping for stiffness K against Lambda; axes with K = 0 get `free_damping`.
Vector6d cartesianDamping(const Vector6d& stiffness, const Vector6d& inertia_diagonal, const Vector6d& free_damping);

// tcp and jacobian: the model's TCP pose and Jacobian at `measured.q`.
JointVector cartesianImpedanceTorque(const FrozenDynamics& model, const PlantParams& params,
                                     const PlantState& measured, const Eigen::Isometry3d& tcp,
                                     const Jacobian& jacobian, const CartesianImpedance& law);

// Torque mode: the client's torque plus gravity and friction compensation.
JointVector torqueModeTorque(const JointVector& user_torque, const JointVector& gravity, const PlantParams& params,
                             const PlantState& measured);

// Joint-space hand guiding: gravity, Coriolis and friction compensated, damped by `damping`.
JointVector jointDragTorque(const FrozenDynamics& model, const PlantParams& params, const PlantState& measured,
                            const JointVector& damping);

}  // namespace xmate::sim
