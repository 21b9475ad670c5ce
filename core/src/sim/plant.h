// SPDX-License-Identifier: Apache-2.0
// The physical arm of the simulator: rigid-body dynamics of the model (dynamics.h) plus what the
// datasheet does not give -- rotor inertia, joint friction, motor torque saturation and the
// holding brakes -- integrated semi-implicitly. All parameters are ESTIMATES, listed in
// docs/simulator_controller.md. Real-time safe: fixed-size Eigen types, no allocation.
#pragma once

#include <Eigen/Cholesky>

#include "model/arm_model.h"
#include "model/robot_spec.h"

namespace xmate::sim {

using model::JointMatrix;
using model::JointVector;

struct PlantParams {
  int dof = 7;
  JointVector armature;             // reflected rotor inertia added to M(q)'s diagonal, kg m^2
  JointVector viscous;              // viscous friction, Nm s/rad
  JointVector coulomb;              // Coulomb friction, Nm
  double coulomb_velocity = 0.05;   // rad/s: speed at which Coulomb friction reaches tanh(1) = 76 %
  JointVector peak_torque;          // motor saturation, Nm
  double brake_deceleration = 50;   // rad/s^2 while the brakes stop a moving joint
};

PlantParams plantParams(const model::RobotSpec& spec);

// Friction torque opposing the joint velocities (smooth Coulomb + viscous).
JointVector frictionTorque(const PlantParams& params, const JointVector& dq);

struct PlantState {
  JointVector q = JointVector::Zero();
  JointVector dq = JointVector::Zero();
};

// The joint-space dynamics of an arm evaluated once at the start of a 1 ms cycle and held for its
// sub-steps: inertia M(q) + armature (unused joints get 1 so it factorises), its factorisation,
// and the bias torques C(q, dq) dq + g(q).
struct FrozenDynamics {
  JointMatrix inertia = JointMatrix::Identity();
  Eigen::LDLT<JointMatrix> inertia_ldlt;
  JointVector bias = JointVector::Zero();
};

void freezeDynamics(const model::ArmModel& arm, const PlantParams& params, const PlantState& state,
                    FrozenDynamics& out);

// Advances the powered arm by dt under the motor and external joint torques:
// (M + armature) ddq = tau_motor + tau_external - bias - friction(dq), then dq += ddq dt, q += dq dt.
// Returns ddq.
JointVector advancePowered(PlantState& state, const FrozenDynamics& dynamics, const PlantParams& params,
                           const JointVector& tau_motor, const JointVector& tau_external, double dt);

// Brakes engaged (motors off): each moving joint decelerates at brake_deceleration to standstill;
// standing joints are held whatever the load.
void advanceBraked(PlantState& state, const PlantParams& params, double dt);

// tau clamped to +-peak_torque.
JointVector saturateTorque(const PlantParams& params, const JointVector& tau);

}  // namespace xmate::sim
