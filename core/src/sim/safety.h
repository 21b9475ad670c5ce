// SPDX-License-Identifier: Apache-2.0
// Supervision of the measured motion: collision from the estimated external joint torques, the
// Cartesian safety box, and the "actual" error bits 0-6. Margins over the command
// limits, because a measured motion overshoots a little: see the constants below and
// docs/simulator_controller.md, "Command rules and the error bits".
#pragma once

#include <Eigen/Core>

#include "model/arm_model.h"
#include "model/robot_spec.h"
#include "sim/command_checks.h"
#include "sim/controller_settings.h"
#include "sim/error_bits.h"

namespace xmate::sim {

inline constexpr double kActualPositionMargin = 0.01;   // rad beyond the soft limit
inline constexpr double kActualVelocityFactor = 1.1;    // x the velocity limits
inline constexpr double kActualAccelerationFactor = 1.5;  // x the acceleration limits

// True if |tau_ext_i| > threshold_i for a joint of the arm.
bool collisionDetected(const JointVector& external_torque, const JointVector& thresholds, int dof);

// True if the TCP position (base frame) lies inside the box (or on its faces).
bool insideSafetyBox(const SafetyBox& box, const Eigen::Vector3d& tcp_position);

// What the controller measured over the last cycle.
struct MeasuredMotion {
  JointVector q = JointVector::Zero();
  JointVector dq = JointVector::Zero();
  JointVector ddq = JointVector::Zero();      // (dq - dq_previous) / dt
  model::Vector6d twist = model::Vector6d::Zero();       // TCP [v; omega], base frame
  model::Vector6d twist_rate = model::Vector6d::Zero();  // (twist - twist_previous) / dt
  double psi_rate = 0;                        // arm angle rate (7-axis)
};

// Which of the measured-motion bits apply to the current activity.
struct ActualChecks {
  bool cartesian = false;      // bit 4 (and 6): Cartesian motion, torque mode, Cartesian hand guiding
  bool elbow = false;          // bit 2 (7-axis only): Cartesian motion and Cartesian hand guiding
  bool accelerations = false;  // bit 5 (and 6): motions, not hand guiding
};

// Bits 0 and 3 always; 5 with accelerations; 4 with cartesian; 6 with both; 2 with elbow.
void checkActualMotion(const MeasuredMotion& m, const JointVector& soft_lower, const JointVector& soft_upper,
                       const JointLimitVectors& joint_limits, const model::CartesianLimits& cartesian_limits,
                       ActualChecks checks, int dof, ErrorBits& bits);

}  // namespace xmate::sim
