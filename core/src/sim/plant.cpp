// SPDX-License-Identifier: Apache-2.0
// Rotor inertia, friction, saturation, brakes and the semi-implicit integration of the arm.
#include "sim/plant.h"

#include <algorithm>
#include <cmath>

#include "model/dynamics.h"

namespace xmate::sim {

PlantParams plantParams(const model::RobotSpec& spec) {
  PlantParams p;
  p.dof = spec.dof;
  p.armature = p.viscous = p.coulomb = p.peak_torque = JointVector::Zero();
  for (int i = 0; i < spec.dof; ++i) {
    // Two joint sizes: the 85 Nm shoulder/elbow drives and the 36 Nm wrist drives.
    const bool big = spec.tau_max[static_cast<size_t>(i)] > 50.0;
    p.armature[i] = big ? 0.1 : 0.05;
    p.viscous[i] = big ? 0.5 : 0.2;
    p.coulomb[i] = big ? 1.5 : 0.6;
    p.peak_torque[i] = 2.0 * spec.tau_max[static_cast<size_t>(i)];
  }
  return p;
}

JointVector frictionTorque(const PlantParams& params, const JointVector& dq) {
  JointVector f = JointVector::Zero();
  for (int i = 0; i < params.dof; ++i)
    f[i] = params.viscous[i] * dq[i] + params.coulomb[i] * std::tanh(dq[i] / params.coulomb_velocity);
  return f;
}

void freezeDynamics(const model::ArmModel& arm, const PlantParams& params, const PlantState& state,
                    FrozenDynamics& out) {
  out.inertia = model::massMatrix(arm, state.q);
  for (int i = 0; i < model::kMaxDof; ++i) out.inertia(i, i) += i < arm.dof ? params.armature[i] : 1.0;
  out.inertia_ldlt.compute(out.inertia);
  out.bias = model::inverseDynamics(arm, state.q, state.dq, JointVector::Zero());
}

JointVector advancePowered(PlantState& state, const FrozenDynamics& dynamics, const PlantParams& params,
                           const JointVector& tau_motor, const JointVector& tau_external, double dt) {
  const JointVector net = tau_motor + tau_external - dynamics.bias - frictionTorque(params, state.dq);
  JointVector ddq = dynamics.inertia_ldlt.solve(net);
  for (int i = params.dof; i < model::kMaxDof; ++i) ddq[i] = 0;
  state.dq += ddq * dt;
  state.q += state.dq * dt;
  return ddq;
}

void advanceBraked(PlantState& state, const PlantParams& params, double dt) {
  const double step = params.brake_deceleration * dt;
  for (int i = 0; i < params.dof; ++i) {
    const double v = state.dq[i];
    state.dq[i] = std::abs(v) <= step ? 0.0 : v - std::copysign(step, v);
    state.q[i] += state.dq[i] * dt;
  }
}

JointVector saturateTorque(const PlantParams& params, const JointVector& tau) {
  JointVector out = tau;
  for (int i = 0; i < model::kMaxDof; ++i)
    out[i] = i < params.dof ? std::clamp(tau[i], -params.peak_torque[i], params.peak_torque[i]) : 0.0;
  return out;
}

}  // namespace xmate::sim
