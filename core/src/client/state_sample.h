// SPDX-License-Identifier: Apache-2.0
// StateSample: the compact copy of one RobotState that the real-time thread pushes into the GUI's
// SPSC ring every cycle (docs/architecture.md, "Threads and hand-offs"). Plain data, fixed size.
#pragma once

#include <array>
#include <cstdint>

#include <xmate/rci_types.h>

namespace xmate::client {

struct StateSample {
  double time = 0;          // s since the session opened, by the client's monotonic clock at receipt
  uint64_t message_id = 0;  // the controller's cycle counter
  std::array<double, 7> q{};      // measured joint positions, rad
  std::array<double, 7> q_c{};    // commanded joint positions, rad
  std::array<double, 7> dq_m{};   // measured joint velocities, rad/s
  std::array<double, 7> tau_m{};  // measured joint torques, Nm
  std::array<double, 7> tau_c{};  // commanded joint torques, Nm
  // The state carries only the external wrench at the TCP in the base frame [F; M]; the GUI maps it
  // to joint space with the model's Jacobian (tau = J^T F) when it wants joint torques.
  std::array<double, 6> tau_ext_in_base{};
  std::array<double, 3> tcp_position{};  // translation of toolTobase_pos_m, m
  uint32_t errors = 0;                   // bit i = RobotState::errors[i]
  RCI::robot::RobotMode robot_mode = RCI::robot::RobotMode::kOther;
  double success_rate = 0;               // control_command_success_rate
};

// Copies the fields above out of a state. Allocation-free.
StateSample makeStateSample(const RCI::robot::RobotState& state, double time);

}  // namespace xmate::client
