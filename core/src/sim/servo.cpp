// SPDX-License-Identifier: Apache-2.0
// Control laws of the simulated controller (servo.h).
#include "sim/servo.h"

#include <algorithm>
#include <cmath>

#include "sim/pose_math.h"

namespace xmate::sim {

JointVector positionControlTorque(const FrozenDynamics& model, const PlantParams& params, const PlantState& measured,
                                  const JointSetpoint& ref) {
  constexpr double kp = kPositionBandwidth * kPositionBandwidth;
  constexpr double kd = 2.0 * kPositionDampingRatio * kPositionBandwidth;
  const JointVector acceleration = ref.ddq + kd * (ref.dq - measured.dq) + kp * (ref.q - measured.q);
  return model.inertia * acceleration + model.bias + frictionTorque(params, measured.dq);
}

JointVector jointImpedanceDamping(const FrozenDynamics& model, const JointVector& stiffness, int dof) {
  constexpr double kFloor = 0.5;  // Nm s/rad
  JointVector d = JointVector::Zero();
  for (int i = 0; i < dof; ++i) d[i] = 2.0 * std::sqrt(stiffness[i] * model.inertia(i, i)) + kFloor;
  return d;
}

JointVector jointImpedanceTorque(const FrozenDynamics& model, const PlantParams& params, const PlantState& measured,
                                 const JointSetpoint& ref, const JointVector& stiffness, const JointVector& damping) {
  const JointVector spring = stiffness.cwiseProduct(ref.q - measured.q);
  const JointVector damper = damping.cwiseProduct(ref.dq - measured.dq);
  return spring + damper + model.inertia * ref.ddq + model.bias + frictionTorque(params, measured.dq);
}

OperationalSpace operationalSpace(const FrozenDynamics& model, const Jacobian& jacobian) {
  const Eigen::Matrix<double, model::kMaxDof, 6> minv_jt = model.inertia_ldlt.solve(jacobian.transpose());
  const Eigen::Matrix<double, 6, 6> a = jacobian * minv_jt + 1e-6 * Eigen::Matrix<double, 6, 6>::Identity();
  const Eigen::Matrix<double, 6, 6> lambda = a.inverse();
  OperationalSpace os;
  os.inertia_diagonal = lambda.diagonal();
  os.nullspace_projector = JointMatrix::Identity() - jacobian.transpose() * lambda * minv_jt.transpose();
  return os;
}

Vector6d cartesianDamping(const Vector6d& stiffness, const Vector6d& inertia_diagonal, const Vector6d& free_damping) {
  Vector6d d;
  for (int i = 0; i < 6; ++i)
    d[i] = stiffness[i] > 0 ? 2.0 * std::sqrt(stiffness[i] * std::max(inertia_diagonal[i], 0.0)) : free_damping[i];
  return d;
}

JointVector cartesianImpedanceTorque(const FrozenDynamics& model, const PlantParams& params,
                                     const PlantState& measured, const Eigen::Isometry3d& tcp,
                                     const Jacobian& jacobian, const CartesianImpedance& law) {
  const Vector6d error = poseError(law.target, tcp);
  const Vector6d twist = jacobian * measured.dq;
  const Vector6d force =
      law.stiffness.cwiseProduct(error) + law.damping.cwiseProduct(law.target_twist - twist) + law.wrench;
  const JointVector posture =
      law.nullspace_stiffness * (law.nullspace_q - measured.q) - law.nullspace_damping * measured.dq;
  return jacobian.transpose() * force + law.nullspace_projector * posture + model.bias +
         frictionTorque(params, measured.dq);
}

JointVector torqueModeTorque(const JointVector& user_torque, const JointVector& gravity, const PlantParams& params,
                             const PlantState& measured) {
  return user_torque + gravity + frictionTorque(params, measured.dq);
}

JointVector jointDragTorque(const FrozenDynamics& model, const PlantParams& params, const PlantState& measured,
                            const JointVector& damping) {
  return model.bias + frictionTorque(params, measured.dq) - damping.cwiseProduct(measured.dq);
}

}  // namespace xmate::sim
