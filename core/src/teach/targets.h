// SPDX-License-Identifier: Apache-2.0
// From taught targets to what the planners take: joint goals for MOVEJ (q, or IK of the pose near
// the current joints) and path points / paths for MOVEL and MOVEC (the pose, or FK of q). Shared by
// the pre-flight trace and the executor so both resolve a target the same way.
#pragma once

#include <array>

#include <xmate/model.h>

#include "model/arm_kinematics.h"
#include "planning/cartesian_path.h"
#include "teach/program.h"

namespace xmate::teach {

// Share of the robot's rated limits a program's speed 1.0 uses: the rest is the reserve that keeps
// a pause or an override change (a time scaling ramped on top of the plan) within the limits.
inline constexpr double kSpeedShare = 0.8;

// MOVEJ goal: target.q, else IK of target.pose (psi: the target's, else the arm angle of q_now)
// nearest q_now. Returns XmateModel::kIkOk or the IK code; q_goal is written only on success.
int jointGoal(const Target& target, const model::ArmKinematics& model, const std::array<double, 7>& q_now,
              std::array<double, 7>& q_goal);

// A MOVEL/MOVEC point: target.pose (psi: the target's, else psi_hold), else FK of target.q with
// its arm angle. Throws std::invalid_argument for a pose that is not a rigid transform.
planning::PathPoint cartesianPoint(const Target& target, const model::ArmKinematics& model, double psi_hold, const char* what);

// The MOVEL line or MOVEC arc from the TCP pose at q_now (with its arm angle) to the instruction's
// target. Throws MotionException for a degenerate arc (planning::makeArcPath's checks) and
// std::invalid_argument for a bad pose.
planning::CartesianPath cartesianPath(const Instruction& instruction, const model::ArmKinematics& model,
                                      const std::array<double, 7>& q_now);

}  // namespace xmate::teach
