// SPDX-License-Identifier: Apache-2.0
// An optional rate limiter for joint position callbacks (an RCI Studio extension, not part of the
// vendor API): it bends a command so that, continued from the controller's last command, the joint
// velocity, acceleration and jerk the controller will compute stay within limits. Use it when a
// callback's targets may jump (a teleoperation device, a vision target, a step): the controller
// would otherwise stop the motion with a command velocity, acceleration or jerk error.
#pragma once

#include <array>

#include <xmate/rci_types.h>
#include <xmate/types.h>

namespace xmate {

// Per-joint bounds, rad/s, rad/s^2, rad/s^3. A joint whose bounds are zero (the 7th joint of a
// 6-axis model) is held where the controller's command is.
struct JointRateLimits {
  std::array<double, 7> velocity{};
  std::array<double, 7> acceleration{};
  std::array<double, 7> jerk{};
};

// The model's rated joint velocity, acceleration and jerk (the bounds the controller checks
// commands against, docs/robot_models.md) times `share` (0 < share <= 1; below 1 leaves a margin
// for the controller's own rounding). Throws std::invalid_argument for a share outside (0, 1].
// Any thread; not for the real-time callback (call it once, before Control()).
JointRateLimits ratedJointRateLimits(XmateType type, double share = 0.95);

// Bends a stream of joint position targets into commands the controller accepts. One limiter per
// motion: make it before Control() and call limit() once per callback.
class JointRateLimiter {
 public:
  explicit JointRateLimiter(const JointRateLimits& limits) : limits_(limits) {}

  // The joint command to send this cycle instead of `desired`. It continues the controller's last
  // command (state.q_c, dq_c, ddq_c) by one 1 ms cycle: towards `desired` moving as the targets
  // have been moving, closing any gap no faster than it can still brake to a stop at the target
  // (so a target that jumps and then holds is reached without overshoot), with the jerk clamped
  // to limits.jerk, the acceleration to limits.acceleration (less near limits.velocity, so the
  // velocity bound is met without exceeding the jerk) and the velocity to limits.velocity. A
  // stream within the limits passes unchanged. Real-time safe: no allocation, no lock, no system
  // call.
  std::array<double, 7> limit(const std::array<double, 7>& desired, const RCI::robot::RobotState& state);

 private:
  struct Target {  // the last target of a joint, its velocity and acceleration
    double q = 0, v = 0, a = 0;
    bool known = false;
  };
  JointRateLimits limits_;
  std::array<Target, 7> targets_{};
};

}  // namespace xmate
