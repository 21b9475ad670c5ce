// SPDX-License-Identifier: Apache-2.0
// Packet fault countdowns and state corruption (see server_faults.h).
#include "sim/server_faults.h"

#include <stdexcept>
#include <string>

namespace xmate::sim {

StateFate applyStateFaults(StateFaults& faults, OutgoingState& out, ServerCounters& counters) {
  if (faults.drop > 0) {
    --faults.drop;
    ++counters.states_dropped;
    return StateFate::kDrop;
  }
  if (faults.corrupt > 0) {
    --faults.corrupt;
    corruptRobotState(out.bytes);
    ++counters.states_corrupted;
  }
  if (faults.wrong_length > 0) {
    --faults.wrong_length;
    out.size = protocol::kRobotStateSize - kWrongLengthDelta;
    ++counters.states_wrong_length;
  }
  if (faults.holding) {
    if (faults.reorder > 0) --faults.reorder;
    ++counters.states_reordered;
    return StateFate::kSendThenHeld;
  }
  if (faults.reorder > 0) {
    --faults.reorder;
    ++counters.states_reordered;
    return StateFate::kHold;
  }
  return StateFate::kSend;
}

void corruptRobotState(protocol::RobotStateBuffer& bytes) {
  bytes[protocol::kRobotStateErrorsOffset] = 0x5A;    // a bool must be 0 or 1
  bytes[protocol::kRobotStateModesOffset + 2] = 0xEE; // robot_mode is 0..6
}

CommandFate applyCommandFaults(CommandFaults& faults, ServerCounters& counters) {
  if (faults.drop > 0) {
    --faults.drop;
    ++counters.commands_dropped;
    return CommandFate::kDrop;
  }
  if (faults.delay > 0) {
    --faults.delay;
    ++counters.commands_delayed;
    return CommandFate::kDelay;
  }
  return CommandFate::kUse;
}

void checkFaultCount(const char* call, int count) {
  if (count < 1 || count > kMaxFaultCount)
    throw std::invalid_argument(std::string(call) + ": the number of datagrams must be 1.." +
                                std::to_string(kMaxFaultCount) + ", got " + std::to_string(count));
}

void checkFaultDelay(const char* call, int delay_ms) {
  if (delay_ms < 0 || delay_ms > kMaxFaultDelayMs)
    throw std::invalid_argument(std::string(call) + ": the delay must be 0.." + std::to_string(kMaxFaultDelayMs) +
                                " ms, got " + std::to_string(delay_ms));
}

PendingFaults pendingFaults(const StateFaults& states, const CommandFaults& commands) {
  PendingFaults p;
  p.drop_states = states.drop;
  p.reorder_states = states.reorder;
  p.corrupt_states = states.corrupt;
  p.wrong_length_states = states.wrong_length;
  p.drop_commands = commands.drop;
  p.delay_commands = commands.delay;
  p.delay_ms = commands.delay > 0 || !commands.delayed.empty() ? commands.delay_ms : 0;
  return p;
}

}  // namespace xmate::sim
