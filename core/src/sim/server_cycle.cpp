// SPDX-License-Identifier: Apache-2.0
// The simulator's cycle thread: every cycle it runs the queued requests, sends the controller's
// state to the client, collects the RobotCommand answering it, and steps the controller by 1 ms.
// Real-time clock: a cycle per millisecond of wall time (absolute sleeps). Lock-step clock: while
// the controller expects commands, each cycle waits for the answer (up to lockstep_timeout_ms).
#include <algorithm>

#include "net/clock.h"
#include "net/realtime.h"
#include "protocol/realtime_codec.h"
#include "sim/server_impl.h"

namespace xmate::sim {
namespace {

constexpr int64_t kCycleNs = 1'000'000;
// The client always gets at least this long to answer a state. If the cycle thread itself was late
// (preempted, process stopped, machine suspended), the next tick moves to a full cycle from now
// instead of running the missed cycles back to back: those would give the client no time to answer
// and blame it for the simulator's own stall (kInstabilityDetection). The stall shows as one long
// period in the client's statistics, not as lost commands.
constexpr int64_t kMinAnswerWindowNs = kCycleNs / 2;
// Lock-step waits are cut into slices so requests, stop() and kill() are served while waiting.
constexpr int64_t kLockStepSliceNs = 2'000'000;

using RCI::robot::RobotCommand;

// ---- Sending --------------------------------------------------------------------------------------

void sendBytes(Server::Impl& s, const OutgoingState& out) {
  if (s.udp.sendTo(s.stream_to, out.bytes.data(), out.size) > 0) ++s.counters.states_sent;
}

// Sends the state (or holds, drops it: packet faults); false when it was dropped.
bool sendState(Server::Impl& s) {
  OutgoingState out;
  protocol::encodeRobotState(s.controller->state(), out.bytes);
  switch (applyStateFaults(s.state_faults, out, s.counters)) {
    case StateFate::kDrop:
      return false;
    case StateFate::kHold:
      s.state_faults.held = out;
      s.state_faults.holding = true;
      return true;
    case StateFate::kSend:
      sendBytes(s, out);
      return true;
    case StateFate::kSendThenHeld:
      sendBytes(s, out);
      sendBytes(s, s.state_faults.held);
      s.state_faults.holding = false;
      return true;
  }
  return true;
}

// ---- Receiving --------------------------------------------------------------------------------------

// The answer a cycle is waiting for, and what arrived.
struct AnswerSlot {
  uint64_t message_id = 0;  // of the state just sent
  bool wanted = false;      // the controller expects an answer to it
  bool matched = false;
  RobotCommand command;
};

// A command has arrived (or its delay is over): it either answers this cycle's state or is stale.
void offerCommand(Server::Impl& s, AnswerSlot& slot, const RobotCommand& command) {
  if (slot.wanted && !slot.matched && command.message_id == slot.message_id) {
    slot.command = command;
    slot.matched = true;
    ++s.counters.commands_used;
  } else {
    ++s.counters.commands_stale;
  }
}

void releaseDueDelayedCommands(Server::Impl& s, AnswerSlot& slot, int64_t now) {
  auto& delayed = s.command_faults.delayed;
  while (!delayed.empty() && delayed.front().release_ns <= now) {
    const RobotCommand command = delayed.front().command;
    delayed.pop_front();
    offerCommand(s, slot, command);
  }
}

void receiveDatagram(Server::Impl& s, AnswerSlot& slot, const uint8_t* data, long size, int64_t now) {
  s.last_client_datagram_ns.store(now, std::memory_order_relaxed);  // a sign of life (the TCP thread's idle rule)
  RobotCommand command;
  if (protocol::decodeRobotCommand(data, size_t(size), command) != protocol::DecodeStatus::kOk) {
    ++s.counters.commands_malformed;
    return;
  }
  ++s.counters.commands_received;
  switch (applyCommandFaults(s.command_faults, s.counters)) {
    case CommandFate::kDrop:
      return;
    case CommandFate::kDelay:
      s.command_faults.delayed.push_back({now + int64_t(s.command_faults.delay_ms) * 1'000'000, command});
      return;
    case CommandFate::kUse:
      offerCommand(s, slot, command);
      return;
  }
}

// Receives until the slot is matched or deadline_ns passes. In lock-step the wait is sliced:
// between slices it serves requests and gives up if the controller stopped expecting an answer.
void awaitAnswer(Server::Impl& s, AnswerSlot& slot, int64_t deadline_ns, bool lockstep) {
  uint8_t buffer[protocol::kRobotCommandSize + 64];
  for (;;) {
    int64_t now = net::monotonicNs();
    releaseDueDelayedCommands(s, slot, now);
    if (slot.matched || s.stopping || s.killed) return;
    if (now >= deadline_ns) {
      // Past the deadline: an answer that arrived in time may still sit in the socket because this
      // thread was late to look (preempted); read what is there without waiting.
      long n = 0;
      while (!slot.matched && (n = s.udp.receiveFrom(buffer, sizeof buffer, nullptr, 0)) > 0)
        receiveDatagram(s, slot, buffer, n, now);
      return;
    }
    int64_t until = deadline_ns;
    if (!s.command_faults.delayed.empty()) until = std::min(until, s.command_faults.delayed.front().release_ns);
    if (lockstep) {
      runQueuedJobs(s);
      if (!s.controller || !s.streaming || !s.controller->expectsCommand()) {
        slot.wanted = false;
        return;
      }
      until = std::min(until, now + kLockStepSliceNs);
    }
    const int64_t wait_us = std::max<int64_t>(0, (until - now) / 1000);
    const long n = s.udp.receiveFrom(buffer, sizeof buffer, nullptr, wait_us);
    if (n > 0) receiveDatagram(s, slot, buffer, n, net::monotonicNs());
  }
}

// ---- One cycle ---------------------------------------------------------------------------------------

void publishAwaitedAnswer(Server::Impl& s, uint64_t message_id) {
  std::lock_guard lock(s.snapshot_mutex);
  s.snapshot.awaiting_answer_to = message_id;
}

void runOneCycle(Server::Impl& s, int64_t& next_tick_ns) {
  AnswerSlot slot;
  slot.message_id = s.controller->state().message_id;
  slot.wanted = s.streaming && s.controller->expectsCommand();
  publishAwaitedAnswer(s, slot.wanted ? slot.message_id : 0);  // before the client can see the state
  const bool dropped = s.streaming && !sendState(s);

  // Lock-step waits for the answer to a state the client got; one it never got is lost at once.
  const bool lockstep = s.config.clock == ClockMode::kLockStep && slot.wanted && !dropped;
  if (lockstep) {
    awaitAnswer(s, slot, net::monotonicNs() + int64_t(s.config.lockstep_timeout_ms) * 1'000'000, true);
    next_tick_ns = net::monotonicNs();  // idle cycles go on in wall time from here
  } else {
    next_tick_ns += kCycleNs;
    const int64_t now = net::monotonicNs();
    if (next_tick_ns - now < kMinAnswerWindowNs) next_tick_ns = now + kCycleNs;
    awaitAnswer(s, slot, next_tick_ns, false);
    net::sleepUntilNs(next_tick_ns);  // an early answer waits for the tick
  }
  publishAwaitedAnswer(s, 0);
  if (!s.controller || s.stopping || s.killed) return;  // a request rebooted it, or we are leaving
  if (slot.wanted && !slot.matched) ++s.counters.commands_lost;
  s.controller->step(slot.matched ? &slot.command : nullptr);
  ++s.counters.cycles;
}

void finishRebootWhenDue(Server::Impl& s) {
  if (net::monotonicNs() < s.reboot_until_ns) return;
  try {
    s.controller = std::make_unique<Controller>(s.config.sim);
  } catch (const std::exception& e) {
    s.log(std::string("reboot failed, retrying in 1 s: ") + e.what());
    s.reboot_until_ns = net::monotonicNs() + 1'000'000'000;
    return;
  }
  applyScene(s);
  s.rebooting = false;
  s.log("reboot done: accepting connections again");
}

// The cycle thread is leaving: from now on callers run their jobs themselves. Jobs queued before
// that moment run here, so every waiter is released.
void handOverJobsAtExit(Server::Impl& s) {
  std::lock_guard lock(s.jobs_mutex);
  s.cycle_alive = false;
  while (!s.jobs.empty()) {
    auto job = std::move(s.jobs.front());
    s.jobs.pop_front();
    try {
      job();
    } catch (const std::exception& e) {
      s.log(std::string("internal error while applying a request: ") + e.what());
    }
    ++s.jobs_done;
  }
  publishSnapshot(s);
  s.jobs_cv.notify_all();
}

void reportStartup(Server::Impl& s) {
  std::string realtime = "normal priority (real-time scheduling not requested)";
  // The cycle thread's stack and the server's own state (the controller model inside it included);
  // what the controller allocates on the heap is locked only where the whole process is (rci-sim).
  if (s.config.realtime)
    realtime = net::enableRealtimeForThisThread(s.config.realtime_priority, {{&s, sizeof s}}).describe();
  {
    std::lock_guard lock(s.snapshot_mutex);
    s.realtime_text = realtime;
  }
  {
    std::lock_guard lock(s.startup_mutex);
    s.cycle_started = true;
  }
  s.startup_cv.notify_all();
}

}  // namespace

void beginReboot(Server::Impl& s) {
  s.log("reboot: session closed, the controller comes back in " + std::to_string(s.config.reboot_pause_ms) + " ms");
  s.streaming = false;
  s.state_faults.holding = false;
  s.command_faults.delayed.clear();
  s.controller.reset();
  s.rebooting = true;
  ++s.reboots_begun;
  ++s.counters.reboots;
  s.reboot_until_ns = net::monotonicNs() + int64_t(s.config.reboot_pause_ms) * 1'000'000;
}

void runCycleThread(Server::Impl& s) {
  net::nameThisThread("rci-sim-cycle");
  reportStartup(s);
  int64_t next_tick_ns = net::monotonicNs();
  while (!s.stopping && !s.killed) {
    runQueuedJobs(s);
    if (s.controller && s.controller->rebootRequested()) beginReboot(s);
    if (s.controller) {
      runOneCycle(s, next_tick_ns);
    } else {
      finishRebootWhenDue(s);
      next_tick_ns = std::max(next_tick_ns + kCycleNs, net::monotonicNs());
      net::sleepUntilNs(next_tick_ns);
    }
    publishSnapshot(s);
  }
  handOverJobsAtExit(s);
}

}  // namespace xmate::sim
