// SPDX-License-Identifier: Apache-2.0
// Packet faults of the simulated controller: countdowns that decide the fate of the next state and
// command datagrams, the random state loss, and the byte surgery that makes a state undecodable.
// No I/O: the cycle thread (server_cycle.cpp) asks and acts.
#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>

#include <xmate/rci_types.h>

#include "protocol/realtime_codec.h"
#include "sim/server.h"

namespace xmate::sim {

// Upper bounds of the fault arguments (a larger number is a typo, not a test).
inline constexpr int kMaxFaultCount = 1'000'000;
inline constexpr int kMaxFaultDelayMs = 60'000;

// An encoded state ready to send (possibly shortened or corrupted).
struct OutgoingState {
  protocol::RobotStateBuffer bytes{};
  size_t size = protocol::kRobotStateSize;
};

// The random loss pattern as it runs (StateLoss): its setting, generator and position.
struct LossRun {
  StateLoss config;
  uint64_t random = 0;      // splitmix64 state, from the seed
  double start_chance = 0;  // per state that may be lost: the chance that a random loss starts there
  int remaining = 0;        // states of the current loss still to drop
  bool rest = false;        // the state after a loss is sent
  int since_burst = 0;      // states since the pattern started or the last burst began
};

struct StateFaults {
  int drop = 0;
  int reorder = 0;  // datagrams left to reorder, even while no datagram is held
  int corrupt = 0;
  int wrong_length = 0;
  bool holding = false;  // the first of a swapped pair waits here for the second
  OutgoingState held;
  LossRun loss;
};

struct DelayedCommand {
  int64_t release_ns = 0;
  RCI::robot::RobotCommand command;
};

struct CommandFaults {
  int drop = 0;
  int delay = 0;
  int delay_ms = 0;
  std::deque<DelayedCommand> delayed;  // in arrival order, hence in release order
};

// What to do with the state about to be sent.
enum class StateFate {
  kDrop,          // do not send it
  kHold,          // keep it; it goes out after the next one (reorder)
  kSend,          // send it
  kSendThenHeld,  // send it, then the held one (the second half of a swapped pair)
};

// Decides the fate of one state, applies corruption or shortening to out, and counts both in
// counters. out must hold the freshly encoded state.
StateFate applyStateFaults(StateFaults& faults, OutgoingState& out, ServerCounters& counters);

// Starts `loss` on `run` from its beginning (generator seeded, first burst burst_every_ms away).
void startStateLoss(LossRun& run, const StateLoss& loss);
// Whether the loss pattern drops the next state; counts what it starts in counters. Allocation-free.
bool nextStateLost(LossRun& run, ServerCounters& counters);
// Throws std::invalid_argument naming the call, the value out of range and the allowed range.
void checkStateLoss(const char* call, const StateLoss& loss);

// Makes an encoded state fail decodeRobotState with kBadValue: errors[0] becomes a bool that is
// neither 0 nor 1 and robot_mode an enum value out of range. The length is unchanged.
void corruptRobotState(protocol::RobotStateBuffer& bytes);

// What a received command turns into.
enum class CommandFate { kUse, kDrop, kDelay };
CommandFate applyCommandFaults(CommandFaults& faults, ServerCounters& counters);

// Validates a fault count (1..kMaxFaultCount) and delay (0..kMaxFaultDelayMs);
// throws std::invalid_argument naming the call and the allowed range.
void checkFaultCount(const char* call, int count);
void checkFaultDelay(const char* call, int delay_ms);

PendingFaults pendingFaults(const StateFaults& states, const CommandFaults& commands);

}  // namespace xmate::sim
