// SPDX-License-Identifier: Apache-2.0
// StandstillWatch (standstill.h): the fastest joint of each state, and how long all were still.
#include "client/standstill.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "client/error_bits.h"

namespace xmate::client {

using RCI::robot::RobotMode;

const Standstill& StandstillWatch::update(const RCI::robot::RobotState& s, int dof) {
  now_.known = true;
  now_.message_id = s.message_id;
  now_.robot_mode = s.robot_mode;
  now_.fastest_joint = 0;
  now_.fastest_speed = 0;
  for (int i = 0; i < dof; ++i) {
    const double speed = std::fmax(std::fabs(s.dq_m[size_t(i)]), std::fabs(s.dq_c[size_t(i)]));
    if (speed > now_.fastest_speed) {
      now_.fastest_speed = speed;
      now_.fastest_joint = i;
    }
  }
  auto count = [](uint32_t& states, bool below) { states = below ? std::min(states + 1, kStillStates) : 0; };
  count(still_states_, now_.fastest_speed < kStillSpeed);
  count(rest_states_, now_.fastest_speed < kRestSpeed);
  now_.still = still_states_ >= kStillStates;
  now_.at_rest = rest_states_ >= kStillStates;
  return now_;
}

bool settling(const Standstill& s, const RCI::robot::RobotState& newest) {
  if (!s.known || s.still || anyError(newest.errors)) return false;
  return newest.robot_mode != RobotMode::kMove && newest.robot_mode != RobotMode::kGuiding;
}

bool stoppingOnItsOwn(const Standstill& s, const RCI::robot::RobotState& newest) {
  return settling(s, newest) && !s.at_rest;
}

StandstillWait travelBetween(const RCI::robot::RobotState& before, const RCI::robot::RobotState& after, int dof) {
  StandstillWait w;
  for (int i = 0; i < dof; ++i) w.joint_travel = std::fmax(w.joint_travel, std::fabs(after.q[size_t(i)] - before.q[size_t(i)]));
  const auto& a = before.toolTobase_pos_m;
  const auto& b = after.toolTobase_pos_m;
  w.tcp_travel = std::sqrt((b[3] - a[3]) * (b[3] - a[3]) + (b[7] - a[7]) * (b[7] - a[7]) + (b[11] - a[11]) * (b[11] - a[11]));
  // The angle of the relative rotation a^T b: acos((trace - 1) / 2).
  double trace = 0;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) trace += a[size_t(4 * c + r)] * b[size_t(4 * c + r)];
  w.rotation_travel = std::acos(std::fmax(-1.0, std::fmin(1.0, (trace - 1) / 2)));
  return w;
}

std::string stillStoppingText(const Standstill& s) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "the arm is still stopping (joint %d at %.2f rad/s)", s.fastest_joint + 1,
                s.fastest_speed);
  return buf;
}

}  // namespace xmate::client
