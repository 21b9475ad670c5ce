// SPDX-License-Identifier: Apache-2.0
// Limit checks on streamed commands (command_checks.h).
#include "sim/command_checks.h"

#include <cmath>

#include "sim/pose_math.h"

namespace xmate::sim {

JointLimitVectors jointLimitVectors(const model::RobotSpec& spec) {
  return {toJointVector(spec.dq_max, spec.dof), toJointVector(spec.ddq_max, spec.dof),
          toJointVector(spec.jerk_max, spec.dof), toJointVector(spec.tau_max, spec.dof),
          toJointVector(spec.dtau_max, spec.dof)};
}

void checkJointPosition(const JointVector& q, const JointVector& lower, const JointVector& upper, int dof,
                        ErrorBits& bits) {
  for (int i = 0; i < dof; ++i)
    if (!(q[i] >= lower[i] - kCommandAbsoluteTolerance && q[i] <= upper[i] + kCommandAbsoluteTolerance))
      raise(bits, kCommandJointPositionLimitsViolation);
}

void checkJointVelocity(const SampledDerivatives<7>& d, const JointLimitVectors& limits, int dof, ErrorBits& bits) {
  for (int i = 0; i < dof; ++i)
    if (exceeds(d.velocity()[i], limits.velocity[i])) raise(bits, kCommandJointVelocityLimitsViolation);
}

void checkJointDerivatives(const SampledDerivatives<7>& d, const JointLimitVectors& limits, int dof,
                           ErrorBits& bits) {
  checkJointVelocity(d, limits, dof, bits);
  for (int i = 0; i < dof; ++i) {
    if (exceeds(d.acceleration()[i], limits.acceleration[i])) raise(bits, kCommandJointAccelerationLimitsViolation);
    if (exceeds(d.jerk()[i], limits.jerk[i])) raise(bits, kCommandJointAccelerationDiscontinuity);
  }
}

void checkCartesianDerivatives(const SampledDerivatives<3>& translation, const SampledDerivatives<3>& rotation,
                               const model::CartesianLimits& limits, ErrorBits& bits) {
  if (exceeds(translation.velocity().norm(), limits.v_trans) || exceeds(rotation.velocity().norm(), limits.v_rot))
    raise(bits, kCommandCartesianVelocityLimitsViolation);
  if (exceeds(translation.acceleration().norm(), limits.a_trans) ||
      exceeds(rotation.acceleration().norm(), limits.a_rot) || exceeds(translation.jerk().norm(), limits.j_trans) ||
      exceeds(rotation.jerk().norm(), limits.j_rot))
    raise(bits, kCommandCartesianAccelerationLimitsViolation);
}

void checkElbowDerivatives(const SampledDerivatives<1>& psi, const model::CartesianLimits& limits, ErrorBits& bits) {
  if (exceeds(psi.velocity()[0], limits.v_elbow) || exceeds(psi.acceleration()[0], limits.a_elbow) ||
      exceeds(psi.jerk()[0], limits.j_elbow))
    raise(bits, kCommandCartesianMotionGeneratorElbowLimitViolation);
}

void checkTorque(const JointVector& total_torque, const SampledDerivatives<7>& user_torque,
                 const JointLimitVectors& limits, int dof, ErrorBits& bits) {
  for (int i = 0; i < dof; ++i) {
    if (exceeds(total_torque[i], limits.torque[i])) raise(bits, kCommandTorqueRangeViolation);
    if (exceeds(user_torque.velocity()[i], limits.torque_rate[i])) raise(bits, kCommandTorqueDiscontinuity);
  }
}

}  // namespace xmate::sim
