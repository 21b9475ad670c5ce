// SPDX-License-Identifier: Apache-2.0
// A straight line in joint space timed by one normalised double-S profile s: 0 -> 1, so every joint
// starts and stops together and none exceeds its own velocity, acceleration and jerk limits times a
// speed ratio. The one joint planner of both robot families: xmate::JointMotionGenerator (the vendor
// API) and the KUKA motions over RSI are built on it (docs/planning.md, "MOVEJ").
#pragma once

#include <array>

#include "model/robot_spec.h"
#include "planning/double_s.h"

namespace xmate::planning {

struct JointLine {
  std::array<double, 7> q_start{};
  std::array<double, 7> delta{};  // goal - start (0 for joints the model does not have)
  DoubleSProfile profile;         // s(t): 0 -> 1 (zero duration for a zero move)
};

// The limits of s: each joint moving delta_i * s keeps |delta_i| ds/dt <= dq_max_i * speed_ratio,
// and the same for acceleration and jerk. The caller checks speed_ratio and the joints' ranges.
// Any thread; allocation-free.
JointLine planJointLine(const model::RobotSpec& spec, const std::array<double, 7>& q_start,
                        const std::array<double, 7>& q_goal, double speed_ratio);

// The joints at time t (clamped to [0, duration]); returns true once t >= duration (q is then
// exactly the goal). Real-time safe.
bool sampleJointLine(const JointLine& line, double t, std::array<double, 7>& q);

}  // namespace xmate::planning
