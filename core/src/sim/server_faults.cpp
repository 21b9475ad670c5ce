// SPDX-License-Identifier: Apache-2.0
// Packet fault countdowns, the random state loss and state corruption (see server_faults.h).
#include "sim/server_faults.h"

#include <cstdio>
#include <stdexcept>
#include <string>

namespace xmate::sim {

StateFate applyStateFaults(StateFaults& faults, OutgoingState& out, ServerCounters& counters) {
  if (faults.drop > 0) {
    --faults.drop;
    ++counters.states_dropped;
    return StateFate::kDrop;
  }
  if (nextStateLost(faults.loss, counters)) {
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

namespace {

// splitmix64: a small, fast generator whose whole state is one word (seeded from any value).
uint64_t nextRandom(uint64_t& state) {
  uint64_t z = (state += 0x9E3779B97F4A7C15ULL);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}

// Uniform in [0, 1).
double nextUniform(uint64_t& state) { return double(nextRandom(state) >> 11) * 0x1.0p-53; }

// Starts a loss of `states` states with this one; returns true (it is lost).
bool beginLoss(LossRun& run, int states, ServerCounters& counters) {
  run.remaining = states - 1;
  run.rest = run.remaining == 0;
  ++counters.states_lost;
  return true;
}

std::string formatValue(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

}  // namespace

void startStateLoss(LossRun& run, const StateLoss& loss) {
  run = LossRun{};
  run.config = loss;
  run.random = loss.seed;
  // A loss of mean length L = 1 + pair_share starts with chance c at each state neither in nor right
  // after a loss. Between two losses come (1 - c) / c sent states on average, then L lost and the
  // one sent after them: the lost share L / ((1 - c) / c + L + 1) is p for c = p / (L (1 - p)).
  const double mean_length = 1 + loss.pair_share;
  if (loss.probability > 0) run.start_chance = loss.probability / (mean_length * (1 - loss.probability));
}

bool nextStateLost(LossRun& run, ServerCounters& counters) {
  const StateLoss& c = run.config;
  if (!c.active()) return false;
  if (c.burst_states > 0) ++run.since_burst;  // restarts at every burst: it never overflows
  if (run.remaining > 0) {
    run.rest = --run.remaining == 0;
    ++counters.states_lost;
    return true;
  }
  if (run.rest) {
    run.rest = false;
    return false;
  }
  if (c.burst_states > 0 && run.since_burst >= c.burst_every_ms) {
    run.since_burst = 0;
    ++counters.loss_bursts;
    return beginLoss(run, c.burst_states, counters);
  }
  if (run.start_chance <= 0 || nextUniform(run.random) >= run.start_chance) return false;
  const bool pair = nextUniform(run.random) < c.pair_share;
  ++(pair ? counters.loss_pairs : counters.loss_singles);
  return beginLoss(run, pair ? 2 : 1, counters);
}

void checkStateLoss(const char* call, const StateLoss& loss) {
  const std::string prefix = std::string(call) + ": ";
  if (!(loss.probability >= 0 && loss.probability <= kMaxLossProbability))
    throw std::invalid_argument(prefix + "the loss probability must be 0.." + formatValue(kMaxLossProbability) +
                                " (0..50 %), got " + formatValue(loss.probability));
  if (!(loss.pair_share >= 0 && loss.pair_share <= 1))
    throw std::invalid_argument(prefix + "the share of pairs must be 0..1 (0..100 %), got " +
                                formatValue(loss.pair_share));
  if (loss.burst_states < 0 || loss.burst_states > kMaxBurstStates)
    throw std::invalid_argument(prefix + "a burst must be 0.." + std::to_string(kMaxBurstStates) + " states, got " +
                                std::to_string(loss.burst_states));
  if ((loss.burst_states == 0) != (loss.burst_every_ms == 0))
    throw std::invalid_argument(prefix + "a burst needs both its length and its period (or neither), got " +
                                std::to_string(loss.burst_states) + " states every " +
                                std::to_string(loss.burst_every_ms) + " ms");
  if (loss.burst_states > 0 && (loss.burst_every_ms <= loss.burst_states || loss.burst_every_ms > kMaxBurstEveryMs))
    throw std::invalid_argument(prefix + "a burst of " + std::to_string(loss.burst_states) +
                                " states needs a period of " + std::to_string(loss.burst_states + 1) + ".." +
                                std::to_string(kMaxBurstEveryMs) + " ms, got " + std::to_string(loss.burst_every_ms));
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
