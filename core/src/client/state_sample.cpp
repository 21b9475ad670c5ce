// SPDX-License-Identifier: Apache-2.0
// makeStateSample: RobotState -> StateSample, run by the real-time thread every cycle.
#include "client/state_sample.h"

#include "client/error_bits.h"

namespace xmate::client {

StateSample makeStateSample(const RCI::robot::RobotState& state, double time) {
  StateSample s;
  s.time = time;
  s.message_id = state.message_id;
  s.q = state.q;
  s.q_c = state.q_c;
  s.dq_m = state.dq_m;
  s.tau_m = state.tau_m;
  s.tau_c = state.tau_c;
  s.tau_ext_in_base = state.tau_ext_in_base;
  s.tcp_position = {state.toolTobase_pos_m[3], state.toolTobase_pos_m[7], state.toolTobase_pos_m[11]};
  s.errors = errorMask(state.errors);
  s.robot_mode = state.robot_mode;
  s.success_rate = state.control_command_success_rate;
  return s;
}

}  // namespace xmate::client
