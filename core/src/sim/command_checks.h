// SPDX-License-Identifier: Apache-2.0
// The command rules (docs/simulator_controller.md, "Command rules and the error bits") applied to
// the commands a client streams: joint position, velocity, acceleration and jerk; Cartesian
// velocity, acceleration and jerk; arm angle rate; torque range and rate. Each check adds the
// matching error bit to `bits`. Derivatives come from SampledDerivatives (divided differences over
// the message_id spacing). Allocation-free.
#pragma once

#include <cmath>

#include "model/arm_model.h"
#include "model/robot_spec.h"
#include "sim/error_bits.h"
#include "sim/sampled_derivatives.h"

namespace xmate::sim {

using model::JointVector;

// A command passes when |value| <= limit * (1 + kCommandRelativeTolerance) + kCommandAbsoluteTolerance.
// Sampling a correct S-curve never exceeds its limits (divided differences are averages), so the
// tolerance only absorbs rounding.
inline constexpr double kCommandRelativeTolerance = 1e-3;
inline constexpr double kCommandAbsoluteTolerance = 1e-9;

inline bool exceeds(double value, double limit) {
  return !(std::abs(value) <= limit * (1.0 + kCommandRelativeTolerance) + kCommandAbsoluteTolerance);
}

// Joint limits as vectors (from RobotSpec), unused joints 0.
struct JointLimitVectors {
  JointVector velocity, acceleration, jerk, torque, torque_rate;
};
JointLimitVectors jointLimitVectors(const model::RobotSpec& spec);

// q finite and within [lower, upper] on the arm's joints; else kCommandJointPositionLimitsViolation.
void checkJointPosition(const JointVector& q, const JointVector& lower, const JointVector& upper, int dof,
                        ErrorBits& bits);

// Velocity -> bit 10, acceleration -> bit 12, jerk -> bit 14 (acceleration discontinuity).
void checkJointDerivatives(const SampledDerivatives<7>& d, const JointLimitVectors& limits, int dof,
                           ErrorBits& bits);

// Like checkJointDerivatives, velocity only (joint motion that an IK produced): bit 10.
void checkJointVelocity(const SampledDerivatives<7>& d, const JointLimitVectors& limits, int dof, ErrorBits& bits);

// Translation and rotation rates against the controller's Cartesian limits: velocity -> bit 11,
// acceleration or jerk -> bit 13 (there is no Cartesian jerk bit).
void checkCartesianDerivatives(const SampledDerivatives<3>& translation, const SampledDerivatives<3>& rotation,
                               const model::CartesianLimits& limits, ErrorBits& bits);

// Arm angle rate, acceleration and jerk against the elbow limits -> bit 9.
void checkElbowDerivatives(const SampledDerivatives<1>& psi, const model::CartesianLimits& limits, ErrorBits& bits);

// Torque mode: the torque the motors are asked for within +-tau_max (bit 18, also for NaN/Inf) and
// the rate of the client's torque within dtau_max (bit 17).
void checkTorque(const JointVector& total_torque, const SampledDerivatives<7>& user_torque,
                 const JointLimitVectors& limits, int dof, ErrorBits& bits);

}  // namespace xmate::sim
