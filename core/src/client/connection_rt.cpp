// SPDX-License-Identifier: Apache-2.0
// The `rci-rt` thread of a client::Connection: receive each RobotState, publish it, and during a
// Control() run call the callback and answer with a RobotCommand. Nothing in the loop allocates,
// locks or logs (tests/client/test_rt_allocations.cpp counts it).
#include "client/connection_rt.h"


#include "client/error_bits.h"
#include "net/clock.h"

namespace xmate::client {
namespace {

using RCI::robot::RobotCommand;
using RCI::robot::RobotMode;
using RCI::robot::RobotState;

constexpr int64_t kReceiveWaitUs = 1000;         // one cycle: short enough to notice `stop` and silence
constexpr int64_t kTimingRefreshNs = 100'000'000;  // SessionTiming is republished every 100 ms

// ---- The end of a run ------------------------------------------------------------------------------

void endRun(Connection::Realtime& rt, ControlOutcome outcome) {
  rt.outcome = outcome;
  rt.last_state = rt.state;
  rt.run_active = false;  // before kDone: the caller may arm the next run right after it
  rt.run_state.store(kRunDone, std::memory_order_release);
  rt.run_state.notify_all();
}

// The result fields of a run, before it starts (or ends without running).
void clearRunResult(Connection::Realtime& rt) {
  rt.log_written = 0;
  rt.cycles = 0;
  rt.exception = nullptr;
  rt.fault = {};
  rt.wrong_length = 0;
  rt.longest_stall_ns = 0;
  rt.stall_message_id = 0;
  rt.states_skipped = 0;
  rt.states_missed_in_run = 0;
  rt.longest_miss = 0;
  rt.miss_message_id = 0;
  rt.states_replayed = 0;
  rt.callback_called = false;
  rt.last_called_id = 0;
}

void logCycle(Connection::Realtime& rt, const RobotCommand* answered) {
  ControlRecord& record = rt.log[rt.log_written % kLogCapacity];
  record.state = rt.state;
  record.command = answered ? *answered : RobotCommand{};
  ++rt.log_written;
}

// ---- Building the command from the callback's answer ----------------------------------------------

// Calls the callback for s and fills rt.command (keeping the motion fields the mode does not use at
// harmless values). Returns the fault found in what the callback returned.
CommandFault callCallback(Connection::Realtime& rt, const RobotState& s, bool& finished) {
  RobotCommand& c = rt.command;
  c.message_id = s.message_id;
  switch (rt.kind) {
    case ControlKind::kJoint: {
      const JointPositions out = (*static_cast<const JointControl*>(rt.callback))(s);
      const CommandFault fault = checkCommand(out, rt.dof);
      c.motion.q_c = out.q;
      if (rt.dof == 6) c.motion.q_c[6] = 0;  // element 6 is unused on 6-axis models and must be 0
      c.motion.toolTobase_pos_c = s.toolTobase_pos_c;
      c.motion.psi_valid = false;
      c.motion.psi_c = s.psi_c;
      c.torque.tau_c = {};
      finished = out.motion_finished;
      return fault;
    }
    case ControlKind::kCartesian: {
      const CartesianPose out = (*static_cast<const CartesianControl*>(rt.callback))(s);
      const CommandFault fault = checkCommand(out);
      c.motion.q_c = s.q_c;
      c.motion.toolTobase_pos_c = out.toolTobase_pos_c;
      c.motion.psi_valid = out.psi_valid;
      c.motion.psi_c = out.psi_valid ? out.psi_c : s.psi_c;
      c.torque.tau_c = {};
      finished = out.motion_finished;
      return fault;
    }
    case ControlKind::kTorque: {
      const Torques out = (*static_cast<const TorqueControl*>(rt.callback))(s);
      const CommandFault fault = checkCommand(out, rt.dof);
      c.motion.q_c = s.q;
      c.motion.toolTobase_pos_c = s.toolTobase_pos_m;
      c.motion.psi_valid = false;
      c.motion.psi_c = s.psi_m;
      c.torque.tau_c = out.tau;
      if (rt.dof == 6) c.torque.tau_c[6] = 0;
      finished = out.motion_finished;
      return fault;
    }
  }
  return {};
}

void sendCommand(Connection::Realtime& rt, const net::Endpoint& to) {
  rt.last_answered_id = rt.command.message_id;
  protocol::encodeRobotCommand(rt.command, rt.encoded);
  if (rt.udp.sendTo(to, rt.encoded.data(), rt.encoded.size()) == long(rt.encoded.size()))
    ++rt.counters.commands_sent;
  else
    ++rt.counters.send_failures;
  ++rt.cycles;
}

// Counts the message_ids between the callback's last state and the newest one: states it missed.
// Returns how many.
uint64_t noteMissedStates(Connection::Realtime& rt) {
  if (!rt.callback_called) return 0;
  const uint64_t missed = rt.state.message_id - rt.last_called_id - 1;
  if (missed == 0) return 0;
  rt.states_missed_in_run += missed;
  if (missed > rt.longest_miss) {
    rt.longest_miss = missed;
    rt.miss_message_id = rt.state.message_id;
  }
  return missed;
}

// MissedStates::kReplay: the callback runs once for each missed message_id (at most
// kMaxReplayedStates, the newest ones), with the newest state stamped with that message_id; its
// outputs are superseded by the newest state's. Stops early when one says motion_finished: that
// output becomes the command. Returns false if the run ended (the callback threw or returned
// something that must not be sent).
bool replayMissedStates(Connection::Realtime& rt, uint64_t missed, bool& finished) {
  const uint64_t count = missed < kMaxReplayedStates ? missed : kMaxReplayedStates;
  rt.replayed = rt.state;
  for (uint64_t id = rt.state.message_id - count; id < rt.state.message_id && !finished; ++id) {
    rt.replayed.message_id = id;
    rt.fault = callCallback(rt, rt.replayed, finished);
    ++rt.states_replayed;
    if (rt.fault.kind != CommandFault::kNone) {
      logCycle(rt, &rt.command);
      endRun(rt, ControlOutcome::kInvalidCommand);
      return false;
    }
  }
  rt.command.message_id = rt.state.message_id;
  return true;
}

// Calls the callback for the newest state (after the missed ones, MissedStates::kReplay) and
// answers it; ends the run if the callback throws or returns something that must not be sent.
void answerWithCallback(Connection::Realtime& rt, const net::Endpoint& from, int64_t received_ns) {
  bool finished = false;
  const uint64_t missed = noteMissedStates(rt);
  rt.callback_called = true;
  rt.last_called_id = rt.state.message_id;
  try {
    if (missed > 0 && rt.replay_missed && !replayMissedStates(rt, missed, finished)) return;
    if (!finished) rt.fault = callCallback(rt, rt.state, finished);
  } catch (...) {
    rt.exception = std::current_exception();
    logCycle(rt, nullptr);
    return endRun(rt, ControlOutcome::kCallbackThrew);
  }
  if (rt.fault.kind != CommandFault::kNone) {
    logCycle(rt, &rt.command);
    return endRun(rt, ControlOutcome::kInvalidCommand);
  }
  rt.command.motion.motion_generation_finished = finished;
  sendCommand(rt, from);
  rt.cost_stats.record(net::monotonicNs() - received_ns);
  logCycle(rt, &rt.command);
  if (finished) {
    rt.phase = RunPhase::kFinishing;
    rt.phase_states = 0;
  }
}

// After motion_generation_finished: repeat the final command (it may be in flight or lost) until
// the controller leaves kMove.
void awaitEnd(Connection::Realtime& rt, bool moving, const net::Endpoint& from, int64_t received_ns) {
  if (!moving) {
    logCycle(rt, nullptr);
    return endRun(rt, ControlOutcome::kFinished);
  }
  if (++rt.phase_states >= kFinishWaitStates) {
    logCycle(rt, nullptr);
    return endRun(rt, ControlOutcome::kFinishNotAcknowledged);
  }
  rt.command.message_id = rt.state.message_id;
  sendCommand(rt, from);
  rt.cost_stats.record(net::monotonicNs() - received_ns);
  logCycle(rt, &rt.command);
}

// Answers the newest state with "hold still": the measured position (joint and Cartesian) and no
// extra torque. Sent between StartMove and the start of the Control() run, and until the controller
// reports the motion running. Each answer is the newest measured position, so that a callback
// starting from the state's q continues the answers without a step; the arm stands still by then
// (Robot::startMove waited for it: standstill.h).
void answerWithHold(Connection::Realtime& rt, const net::Endpoint& from, int64_t received_ns) {
  const RobotState& s = rt.state;
  RobotCommand& c = rt.command;
  c = RobotCommand{};
  c.message_id = s.message_id;
  c.motion.q_c = s.q;
  if (rt.dof == 6) c.motion.q_c[6] = 0;
  c.motion.toolTobase_pos_c = s.toolTobase_pos_m;
  c.motion.psi_c = s.psi_m;
  sendCommand(rt, from);
  rt.cost_stats.record(net::monotonicNs() - received_ns);
}

// Between StartMove and Control(): hold every state that arrived after the request (earlier ones
// were sent before the controller started the motion and are not expected), unless the motion
// already ended with an error.
void holdIfRequested(Connection::Realtime& rt, const net::Endpoint& from, int64_t received_ns) {
  if (rt.hold_kind.load(std::memory_order_acquire) == 0) return;
  if (rt.last_state_ns < rt.motion_requested_ns.load(std::memory_order_relaxed)) return;
  if (anyError(rt.state.errors)) return;
  answerWithHold(rt, from, received_ns);
}

// Until the controller reports robot_mode kMove: "hold still", as between StartMove and Control().
// States that still report kIdle were computed before the controller executed StartMove (the
// real-time thread may read them late, after the run was armed); the callback must not see them,
// or the motion's clock would start before the controller's (a step into the trajectory).
void awaitStart(Connection::Realtime& rt, const net::Endpoint& from, int64_t received_ns) {
  if (++rt.phase_states >= kStartWaitStates) {
    logCycle(rt, nullptr);
    return endRun(rt, ControlOutcome::kNotStarted);
  }
  answerWithHold(rt, from, received_ns);
  logCycle(rt, &rt.command);
}

// One cycle of an armed run for the newest state: "hold still" until the first state reporting
// robot_mode kMove, then the callback answers every state until the controller has ended the
// motion. Until the run started, answerWithHold answered since StartMove.
void stepRun(Connection::Realtime& rt, const net::Endpoint& from, int64_t received_ns) {
  const RobotState& s = rt.state;
  if (anyError(s.errors)) {
    logCycle(rt, nullptr);
    return endRun(rt, ControlOutcome::kControllerError);
  }
  const bool moving = s.robot_mode == RobotMode::kMove;
  switch (rt.phase) {
    case RunPhase::kWaitingForStart:
      if (!moving) return awaitStart(rt, from, received_ns);
      rt.phase = RunPhase::kRunning;
      return answerWithCallback(rt, from, received_ns);
    case RunPhase::kRunning:
      if (!moving) {
        logCycle(rt, nullptr);
        return endRun(rt, ControlOutcome::kEndedByController);
      }
      return answerWithCallback(rt, from, received_ns);
    case RunPhase::kFinishing:
      return awaitEnd(rt, moving, from, received_ns);
  }
}

// ---- Receiving -------------------------------------------------------------------------------------

bool sameHost(const net::Endpoint& a, const net::Endpoint& b) {
  return a.addr.sin_addr.s_addr == b.addr.sin_addr.s_addr;
}

void handleWrongLength(Connection::Realtime& rt, long size) {
  ++rt.counters.states_wrong_length;
  rt.last_wrong_length.store(uint64_t(size), std::memory_order_relaxed);
  rt.wrong_length_count.fetch_add(1, std::memory_order_release);
  if (rt.run_active) {
    rt.wrong_length = size_t(size);
    endRun(rt, ControlOutcome::kWrongLength);
  }
}

// Decodes and publishes one datagram of the right size; false if it was dropped.
bool acceptState(Connection::Realtime& rt, long size, int64_t received_ns) {
  if (size != long(protocol::kRobotStateSize)) {
    handleWrongLength(rt, size);
    return false;
  }
  if (protocol::decodeRobotState(rt.datagram.data(), size_t(size), rt.incoming) != protocol::DecodeStatus::kOk) {
    ++rt.counters.states_bad_value;
    return false;
  }
  if (rt.have_state && rt.incoming.message_id <= rt.last_id) {
    ++rt.counters.states_stale;
    return false;
  }
  rt.state = rt.incoming;
  if (rt.have_state) {
    const uint64_t missed = rt.state.message_id - rt.last_id - 1;
    if (missed > 0) {
      rt.counters.states_missed += missed;
      rt.period_stats.recordLost(missed);
    }
    rt.period_stats.record(received_ns - rt.last_state_ns);
  }
  rt.have_state = true;
  rt.last_id = rt.state.message_id;
  rt.last_state_ns = received_ns;
  ++rt.counters.states_received;
  rt.latest.store(rt.state);  // hand-off: seqlock (newest state for receiveRobotState())
  rt.standstill.store(rt.standstill_watch.update(rt.state, rt.dof));  // hand-off: seqlock
  const double t = double(received_ns - rt.session_start_ns) * 1e-9;
  if (!rt.samples->push(makeStateSample(rt.state, t)))  // hand-off: SPSC ring to the GUI
    ++rt.counters.samples_dropped;
  return true;
}

void publishTiming(Connection::Realtime& rt, int64_t now_ns) {
  if (now_ns < rt.next_timing_ns) return;
  rt.next_timing_ns = now_ns + kTimingRefreshNs;
  SessionTiming t;
  t.period = rt.period_stats.summary();
  t.cost = rt.cost_stats.summary();
  t.counters = rt.counters;
  rt.timing.store(t);  // hand-off: seqlock (any reader)
}

void checkSilence(Connection::Realtime& rt, int64_t now_ns) {
  if (!rt.run_active) return;
  const int64_t since = rt.last_state_ns > rt.run_start_ns ? rt.last_state_ns : rt.run_start_ns;
  if (now_ns - since > rt.silence_limit_ns) endRun(rt, ControlOutcome::kStateTimeout);
}

// Publishes one received datagram if it is a good, newer state from the controller; false if not.
bool acceptDatagram(Connection::Realtime& rt, long size, const net::Endpoint& from, int64_t received_ns) {
  if (size <= 0) return false;
  if (!sameHost(from, rt.controller)) {
    ++rt.counters.states_foreign;
    return false;
  }
  if (!acceptState(rt, size, received_ns)) return false;
  rt.last_from = from;
  return true;
}

// Answers the newest accepted state: the run's cycle, or "hold still" between StartMove and Control().
void answerNewest(Connection::Realtime& rt, int64_t received_ns) {
  if (rt.run_active)
    stepRun(rt, rt.last_from, received_ns);
  else
    holdIfRequested(rt, rt.last_from, received_ns);
}

// The first datagram of a wake-up and every one queued behind it: all are published, only the
// newest state is answered. A backlog means the loop stalled (or the controller sent a burst).
// after_longest_stall: this wake-up ends the run's longest stall so far (noteWakeUp).
void processWakeUp(Connection::Realtime& rt, long size, const net::Endpoint& from, int64_t received_ns,
                   bool after_longest_stall) {
  uint64_t accepted = acceptDatagram(rt, size, from, received_ns) ? 1 : 0;
  if (size > 0) {
    net::Endpoint next_from;
    long n = 0;
    while ((n = rt.udp.receiveFrom(rt.datagram.data(), rt.datagram.size(), &next_from, 0)) > 0)
      accepted += acceptDatagram(rt, n, next_from, received_ns) ? 1 : 0;
  }
  if (after_longest_stall && rt.run_active) rt.stall_message_id = rt.last_id;  // before the run may end
  if (accepted == 0) return checkSilence(rt, received_ns);
  const uint64_t skipped = accepted - 1;
  rt.counters.states_skipped += skipped;
  if (rt.run_active) rt.states_skipped += skipped;
  answerNewest(rt, received_ns);
}

// During a run, remembers the longest time the loop did not run (a healthy loop wakes at least
// every cycle: a state arrives, or the 1 ms receive timeout expires). True for a new longest.
bool noteWakeUp(Connection::Realtime& rt, int64_t now_ns) {
  const int64_t gap = now_ns - rt.last_wake_ns;
  rt.last_wake_ns = now_ns;
  if (!rt.run_active || gap <= rt.longest_stall_ns) return false;
  rt.longest_stall_ns = gap;
  return true;
}

}  // namespace

void beginRunIfArmed(Connection::Realtime& rt, int64_t now_ns) {
  const bool armed = rt.run_state.load(std::memory_order_acquire) == kRunArmed;
  if (!armed || rt.run_active) {
    rt.run_active = armed;
    return;
  }
  // A new run: its request fields were written before kArmed was stored.
  rt.run_active = true;
  rt.phase = RunPhase::kWaitingForStart;
  rt.phase_states = 0;
  rt.run_start_ns = now_ns;
  clearRunResult(rt);
  rt.command = RobotCommand{};
  // The newest state may be one the controller waits for and nobody answered yet (no hold was
  // requested, e.g. a tool driving Connection directly): answer it now if it came after StartMove.
  const bool unanswered = rt.have_state && rt.state.message_id != rt.last_answered_id &&
                          rt.last_state_ns >= rt.motion_requested_ns.load(std::memory_order_relaxed);
  if (unanswered) stepRun(rt, rt.last_from, now_ns);
}

void processDatagram(Connection::Realtime& rt, long size, const net::Endpoint& from, int64_t received_ns) {
  if (acceptDatagram(rt, size, from, received_ns))
    answerNewest(rt, received_ns);
  else
    checkSilence(rt, received_ns);
}

void finishArmedRunAsClosed(Connection::Realtime& rt) {
  uint32_t armed = kRunArmed;
  if (!rt.run_state.compare_exchange_strong(armed, kRunClosing)) return;
  clearRunResult(rt);
  endRun(rt, ControlOutcome::kSessionClosed);
}

void runRealtimeThread(Connection::Realtime& rt) {
  net::nameThisThread("rci-rt");
  if (rt.try_realtime)
    rt.status = net::enableRealtimeForThisThread(
        rt.realtime_priority, {{&rt, sizeof rt}, {rt.samples, sizeof *rt.samples}});
  else
    rt.status.reason = "real-time scheduling not requested (SessionOptions::realtime = false)";
  rt.started.store(1, std::memory_order_release);
  rt.started.notify_all();

  rt.next_timing_ns = rt.last_wake_ns = net::monotonicNs();
  while (!rt.stop.load(std::memory_order_acquire)) {
    net::Endpoint from;
    const long n = rt.udp.receiveFrom(rt.datagram.data(), rt.datagram.size(), &from, kReceiveWaitUs);
    const int64_t now = net::monotonicNs();
    beginRunIfArmed(rt, now);
    processWakeUp(rt, n, from, now, noteWakeUp(rt, now));
    publishTiming(rt, now);
  }
  beginRunIfArmed(rt, net::monotonicNs());
  if (rt.run_active) endRun(rt, ControlOutcome::kSessionClosed);
}

}  // namespace xmate::client
