// SPDX-License-Identifier: Apache-2.0
// Blocking point-to-point moves built on Robot::Control (docs/api.md, "MOVEJ, MOVEL, MOVEC"): MOVEJ in joint space,
// MOVEL on a straight line, MOVEC on a circular arc, all with jerk-limited timing.
#pragma once

#include <array>

#include <xmate/model.h>
#include <xmate/robot.h>

namespace xmate {

// A TCP pose (4x4 row-major, base frame) with an optional arm angle.
struct cart_pos {
  std::array<double, 16> pos{};
  bool psi_valid = false;
  double psi = 0;
};

// speed_ratio in (0, 1]: 1.0 plans with 85 % of the rated velocity, acceleration and jerk, keeping
// the rest to rejoin the plan after lost states without breaking a limit. Before anything moves the
// target (and for MOVEL/MOVEC the path) is checked against the joint range, the soft limits set with
// setJointLimit and the safety box set with setCartesianLimit; a motion that would leave them throws
// MotionException naming the joint or face, the limit and the value (moving back towards them is
// allowed). Throw MotionException when planning fails (unreachable, collinear arc points, limits),
// when the arm is still stopping after a stop (startMove), and ControlException when the controller
// aborts. Caller's thread, blocking, not real-time safe (never from a Control() callback: they run
// Control() themselves). Return true when the target was reached.
bool MOVEJ(double speed_ratio, const std::array<double, 7>& q_start, const std::array<double, 7>& q_target,
           Robot& robot);
bool MOVEL(double speed_ratio, cart_pos& start, cart_pos& target, Robot& robot);
bool MOVEL(double speed_ratio, cart_pos& start, cart_pos& target, Robot& robot, XmateModel& model);
bool MOVEC(double speed_ratio, cart_pos& start, cart_pos& mid, cart_pos& target, Robot& robot);
bool MOVEC(double speed_ratio, cart_pos& start, cart_pos& mid, cart_pos& target, Robot& robot,
           XmateModel& model);

}  // namespace xmate
