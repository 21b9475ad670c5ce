// SPDX-License-Identifier: Apache-2.0
// Collision, safety box and measured-motion checks (safety.h).
#include "sim/safety.h"

#include <cmath>

namespace xmate::sim {

bool collisionDetected(const JointVector& external_torque, const JointVector& thresholds, int dof) {
  for (int i = 0; i < dof; ++i)
    if (std::abs(external_torque[i]) > thresholds[i]) return true;
  return false;
}

bool insideSafetyBox(const SafetyBox& box, const Eigen::Vector3d& tcp_position) {
  const Eigen::Vector3d local = box.frame.inverse() * tcp_position;
  for (int i = 0; i < 3; ++i)
    if (std::abs(local[i]) > 0.5 * box.size[i]) return false;
  return true;
}

void checkActualMotion(const MeasuredMotion& m, const JointVector& soft_lower, const JointVector& soft_upper,
                       const JointLimitVectors& joint_limits, const model::CartesianLimits& cartesian_limits,
                       ActualChecks checks, int dof, ErrorBits& bits) {
  for (int i = 0; i < dof; ++i) {
    if (m.q[i] < soft_lower[i] - kActualPositionMargin || m.q[i] > soft_upper[i] + kActualPositionMargin)
      raise(bits, kActualJointPositionLimitsViolation);
    if (std::abs(m.dq[i]) > kActualVelocityFactor * joint_limits.velocity[i])
      raise(bits, kActualJointVelocityLimitsViolation);
    if (checks.accelerations && std::abs(m.ddq[i]) > kActualAccelerationFactor * joint_limits.acceleration[i])
      raise(bits, kActualJointAccelerationLimitsViolation);
  }
  if (checks.elbow && dof == 7 && std::abs(m.psi_rate) > kActualVelocityFactor * cartesian_limits.v_elbow)
    raise(bits, kActualCartesianMotionGeneratorElbowLimitViolation);
  if (!checks.cartesian) return;
  if (m.twist.head<3>().norm() > kActualVelocityFactor * cartesian_limits.v_trans ||
      m.twist.tail<3>().norm() > kActualVelocityFactor * cartesian_limits.v_rot)
    raise(bits, kActualCartesianVelocityLimitsViolation);
  if (checks.accelerations &&
      (m.twist_rate.head<3>().norm() > kActualAccelerationFactor * cartesian_limits.a_trans ||
       m.twist_rate.tail<3>().norm() > kActualAccelerationFactor * cartesian_limits.a_rot))
    raise(bits, kActualCartesianAccelerationLimitsViolation);
}

}  // namespace xmate::sim
