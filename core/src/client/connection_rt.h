// SPDX-License-Identifier: Apache-2.0
// The real-time side of a client::Connection: the state the `rci-rt` thread owns, the values it
// publishes, and the Control() run it executes. Shared by connection.cpp (caller's thread) and
// connection_rt.cpp (the thread). Every field says who writes it and how it is handed over.
#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <exception>

#include <xmate/exception.h>
#include <xmate/rci_types.h>

#include "client/connection.h"
#include "client/standstill.h"
#include "protocol/realtime_codec.h"

namespace xmate::client {

// Hand-off of one Control() run (docs/architecture.md): the caller fills the request fields and
// stores kArmed (release); the real-time thread runs it and, when it ends, fills the result fields
// and stores kDone (release) + notify; the caller waits on it (std::atomic::wait), reads the
// result and stores kIdle. Between kArmed and kDone only the real-time thread touches the run.
// Runs are armed with a compare-and-swap from kIdle. When the session closes with a run armed that
// the thread never took (it had already stopped), the run is ended as kSessionClosed by whichever
// thread wins the compare-and-swap kArmed -> kClosing (finishArmedRunAsClosed).
enum RunState : uint32_t { kRunIdle = 0, kRunArmed = 1, kRunDone = 2, kRunClosing = 3 };

enum class RunPhase {
  kWaitingForStart,  // the controller has not yet reported robot_mode kMove: answered "hold still"
  kRunning,          // calling the callback every cycle; leaving kMove ends the run
  kFinishing,        // motion_generation_finished sent; waiting for the controller to leave kMove
};

// How many states the run tolerates in each waiting phase before it gives up.
inline constexpr uint32_t kStartWaitStates = 1000;   // 1 s for the controller to start the motion
inline constexpr uint32_t kFinishWaitStates = 200;   // 200 ms for it to acknowledge the end
inline constexpr size_t kLogCapacity = 64;           // power of two >= kControlLogLength

struct Connection::Realtime {
  // ---- Set by the caller before the thread starts; read-only afterwards -------------------------
  net::UdpSocket udp;              // owned by the thread while it runs
  net::Endpoint controller;        // datagrams from another IP are dropped
  int dof = 7;
  int64_t session_start_ns = 0;
  int64_t silence_limit_ns = 0;    // SessionTimeouts::control_silence_ms
  bool try_realtime = true;
  int realtime_priority = 80;
  SampleRing* samples = nullptr;

  // ---- Lifecycle ----------------------------------------------------------------------------------
  std::atomic<bool> stop{false};          // caller -> thread: leave the loop
  std::atomic<uint32_t> started{0};       // thread -> caller: 1 once `status` is written (then notify)
  net::RealtimeStatus status;             // written by the thread before `started`

  // ---- Published by the thread (lock-free) --------------------------------------------------------
  net::Seqlock<RCI::robot::RobotState> latest;  // newest in-order state (seqlock: any reader)
  std::atomic<uint64_t> latest_base{0};         // latest.version() when the session opened (caller; any reader)
  net::Seqlock<SessionTiming> timing;           // refreshed every 100 ms (seqlock: any reader)
  net::Seqlock<Standstill> standstill;          // with every accepted state (seqlock: any reader)
  std::atomic<uint64_t> wrong_length_count{0};  // datagrams of another size (atomic counter)
  std::atomic<uint64_t> last_wrong_length{0};

  // ---- Thread only ----------------------------------------------------------------------------------
  bool have_state = false;
  uint64_t last_id = 0;
  int64_t last_state_ns = 0;
  int64_t last_wake_ns = 0;         // when the loop last returned from its receive (stall detection)
  int64_t next_timing_ns = 0;
  net::CycleStats period_stats{1000.0, 1500.0};
  net::CycleStats cost_stats{1000.0, 1000.0};
  SessionCounters counters;
  StandstillWatch standstill_watch;
  alignas(8) std::array<uint8_t, protocol::kRobotStateSize + 64> datagram{};
  RCI::robot::RobotState incoming;  // the datagram being decoded
  RCI::robot::RobotState state;     // the newest accepted state
  net::Endpoint last_from;          // where it came from (commands go back there)
  protocol::RobotCommandBuffer encoded{};

  // ---- Holding still between StartMove and Control() (Connection::beginMotionHold) ---------------
  std::atomic<uint32_t> hold_kind{0};               // caller -> thread: 0 none, else ControlKind + 1
  std::atomic<int64_t> motion_requested_ns{0};      // caller -> thread: when StartMove was sent
  uint64_t last_answered_id = 0;                    // thread: message_id of the last command sent

  // ---- The Control() run (see RunState) -------------------------------------------------------------
  std::atomic<uint32_t> run_state{kRunIdle};
  bool run_active = false;          // thread: the run it is executing (kArmed seen, not yet kDone)
  // request (caller, before kArmed)
  ControlKind kind = ControlKind::kJoint;
  const void* callback = nullptr;  // const JointControl* / CartesianControl* / TorqueControl*
  bool replay_missed = true;       // MissedStates::kReplay
  // progress (thread)
  RunPhase phase = RunPhase::kWaitingForStart;
  int64_t run_start_ns = 0;
  uint32_t phase_states = 0;       // states seen in the current waiting phase
  RCI::robot::RobotCommand command;  // the last command sent
  bool callback_called = false;    // the callback has run for a state of this run
  uint64_t last_called_id = 0;     // the message_id it last ran for
  RCI::robot::RobotState replayed; // the state handed to it for a missed message_id
  std::array<ControlRecord, kLogCapacity> log{};
  uint64_t log_written = 0;
  // result (thread, before kDone)
  ControlOutcome outcome = ControlOutcome::kFinished;
  RCI::robot::RobotState last_state;
  uint64_t cycles = 0;
  std::exception_ptr exception;
  CommandFault fault;
  size_t wrong_length = 0;
  int64_t longest_stall_ns = 0;     // the longest time between two wake-ups of the loop during the run
  uint64_t stall_message_id = 0;    // the newest state when the loop woke from that stall
  uint64_t states_skipped = 0;      // states published but not answered (a newer one was queued)
  uint64_t states_missed_in_run = 0;  // message_ids the callback did not run for in time
  uint64_t longest_miss = 0;        // the longest run of them ...
  uint64_t miss_message_id = 0;     // ... and the message_id that ended it
  uint64_t states_replayed = 0;     // missed message_ids the callback was called for afterwards
};

// At most this many missed states are replayed before the newest one: the controller stops a motion
// after about 15 commands lost in a row, so older ones would only cost time.
inline constexpr uint64_t kMaxReplayedStates = 20;

// The thread's body (connection_rt.cpp). Each wake-up reads every datagram already queued; all
// states are published, only the newest is answered (after a stall the controller waits for the
// answer to its newest state: answers to older ones would arrive too late to be used).
void runRealtimeThread(Connection::Realtime& rt);

// Ends a run that is armed but that no real-time thread will take (the thread was joined) with
// kSessionClosed, and wakes its caller. No-op when no run is armed. Not on the real-time thread.
void finishArmedRunAsClosed(Connection::Realtime& rt);

// One step of that body, public so that `rci-cli bench client` can time the exact production path:
// beginRunIfArmed() notices a newly armed run; processDatagram() handles the `size` bytes in
// rt.datagram (size <= 0: nothing arrived) -- decode, publish, and during a run the callback,
// encode and send. Real-time thread only; real-time safe (no allocation, no lock).
void beginRunIfArmed(Connection::Realtime& rt, int64_t now_ns);
void processDatagram(Connection::Realtime& rt, long size, const net::Endpoint& from, int64_t received_ns);

}  // namespace xmate::client
