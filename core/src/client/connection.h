// SPDX-License-Identifier: Apache-2.0
// client::Connection: one session with one robot controller (docs/client.md, docs/protocol.md).
// It owns the TCP command channel (tcp_session.h) and the real-time thread that owns the UDP socket
// and runs the 1 kHz exchange (docs/architecture.md, "Threads and hand-offs"). xmate::Robot is a
// thin layer of validation and message encoding on top; RCI Studio's own tools use it directly.
#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <exception>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include <xmate/exception.h>
#include <xmate/rci_types.h>
#include <xmate/types.h>

#include "client/command_checks.h"
#include "client/limit_check.h"
#include "client/standstill.h"
#include "client/state_sample.h"
#include "client/tcp_session.h"
#include "net/cycle_stats.h"
#include "net/realtime.h"
#include "net/seqlock.h"
#include "net/spsc_ring.h"
#include "net/udp_socket.h"

namespace xmate::client {

// Time limits of a session (docs/protocol.md, "Timeouts").
struct SessionTimeouts {
  int connect_ms = 2000;          // TCP connect and the Connect handshake
  int response_ms = 2000;         // any other TCP response
  int motion_response_ms = 5000;  // StartMove, StopMove, AutomaticErrorRecovery, RebootRobot
  int state_ms = 1000;            // receiveRobotState(): no state for this long -> UdpException
  int control_silence_ms = 100;   // during Control(): no state for this long -> UdpException
};

struct SessionOptions {
  SessionTimeouts timeouts;
  bool realtime = true;        // try SCHED_FIFO for the real-time thread and lock its memory in RAM
  int realtime_priority = 80;
  // Where the session reports what it could not get (real-time refused, ...). Default: stderr.
  std::function<void(const std::string&)> log;
};

// What the real-time thread counted since the session opened.
struct SessionCounters {
  uint64_t states_received = 0;      // well-formed, in-order states (published)
  uint64_t states_wrong_length = 0;  // datagrams of another size (another protocol version)
  uint64_t states_bad_value = 0;     // right size but undecodable (impossible bool or enum)
  uint64_t states_stale = 0;         // message_id not newer than the last one (reordered, duplicated)
  uint64_t states_foreign = 0;       // datagrams from an address other than the controller's
  uint64_t states_missed = 0;        // gaps in message_id (states that never arrived)
  uint64_t states_skipped = 0;       // published but not answered: a newer state was already queued (a stall)
  uint64_t commands_sent = 0;
  uint64_t send_failures = 0;        // sendto refused
  uint64_t samples_dropped = 0;      // GUI ring full
};

// Timing of the exchange, refreshed by the real-time thread every 100 ms (timing()).
struct SessionTiming {
  net::CycleSummary period;  // between successive received states; lost = message_id gaps
  net::CycleSummary cost;    // decode + callback + encode + send, cycles that were answered
  SessionCounters counters;
};

// What a Control() run does with states its callback did not see: datagrams lost on the way, and
// states left unanswered behind a newer one after a stall of the client's loop.
enum class MissedStates {
  // Before answering the newest state, the callback is called once per missed message_id, oldest
  // first, with the newest state whose message_id is set to the missed one; those outputs are not
  // sent (only one that returns motion_finished is: it ends the motion). Programs that keep time by
  // counting calls (time += 0.001, as in the vendor manual) stay on the controller's clock.
  kReplay,
  // The callback sees the gap in message_id: for generators that keep time by message_id and
  // bridge gaps themselves (MOVEJ/MOVEL/MOVEC, the teach executor: stall_bridge.h).
  kSkip,
};

// How a Control() run ended (runControl()).
enum class ControlOutcome {
  kFinished,              // the callback returned motion_finished and the controller ended the motion
  kControllerError,       // a state carried error bits
  kEndedByController,     // the controller left the motion without error bits (e.g. a guard stop)
  kNotStarted,            // the controller never reported the motion as running
  kFinishNotAcknowledged, // the controller kept moving after motion_generation_finished
  kCallbackThrew,         // the callback threw (exception holds it)
  kInvalidCommand,        // the callback returned NaN/Inf or a non-homogeneous pose
  kStateTimeout,          // no state for control_silence_ms
  kWrongLength,           // a state datagram of another size arrived
  kSessionClosed,         // the session was closed during the run
};

struct ControlResult {
  ControlOutcome outcome = ControlOutcome::kFinished;
  ControlKind kind = ControlKind::kJoint;
  RCI::robot::RobotState last_state;  // the newest state of the run
  uint64_t cycles = 0;                // commands sent
  std::exception_ptr exception;       // kCallbackThrew
  CommandFault fault;                 // kInvalidCommand
  size_t wrong_length = 0;            // kWrongLength: the datagram's size
  std::vector<ControlRecord> log;     // the last cycles, oldest first (at most kControlLogLength)
  // The client's own timing during the run: the longest time its real-time loop did not run (a
  // healthy loop runs at least once per 1 ms cycle), the newest state when it ran again, and the
  // states it published but did not answer because a newer one was already queued.
  double longest_stall_ms = 0;
  uint64_t stall_message_id = 0;
  uint64_t states_skipped = 0;
  // States the callback missed (lost on the way or skipped after a stall): how many in all, the
  // longest run of consecutive ones and the message_id that ended it, and how many were replayed
  // (MissedStates::kReplay).
  uint64_t states_missed = 0;
  uint64_t longest_miss = 0;
  uint64_t miss_message_id = 0;
  uint64_t states_replayed = 0;
};

inline constexpr size_t kControlLogLength = 50;
using SampleRing = net::SpscRing<StateSample, 4096>;

class Connection {
 public:
  Connection(const std::string& ip, uint16_t port, XmateType type, SessionOptions options = {});
  ~Connection();  // close()s
  Connection(const Connection&) = delete;
  Connection& operator=(const Connection&) = delete;

  // Opening and closing are serialised: any thread may call open(), close(), ensureOpen() and
  // isOpen() at any time (docs/client.md, "Threads").
  // Opens the TCP session, binds the UDP socket on a free port, starts the real-time thread and
  // performs the Connect handshake. No-op when open. Throws TcpException (unreachable),
  // NetworkException (thread, socket) or ProtocolException (incompatible library version).
  void open();
  // What every Robot call does first: open() if this connection was never opened; if it was and
  // the session broke or was closed since, throws NetworkException -- a lost session is re-opened
  // only on purpose (Robot::connect() / reconnect(), from the thread that owns the session).
  void ensureOpen();
  // Stops the real-time thread and closes both sockets; a Control() run in progress (or armed
  // right now) ends with kSessionClosed. Safe to call twice, from any thread.
  void close();
  bool isOpen() const;

  const std::string& ip() const { return ip_; }
  uint16_t port() const { return port_; }
  XmateType type() const { return type_; }
  const SessionOptions& options() const { return options_; }

  // ---- TCP (any thread; serialised) -----------------------------------------------------------
  // Sends one request and returns the response payload (starting with its Command code). On a
  // broken connection the session is closed (open() again, or Robot::reconnect()).
  template <class Request>
  std::vector<uint8_t> request(const char* call, const Request& message, int timeout_ms) {
    return requestFrame(call, [&](uint32_t sequence) { return protocol::encodeFrame(sequence, message); },
                        commandOf(message), timeout_ms);
  }
  std::vector<uint8_t> requestFrame(const char* call, const std::function<protocol::Frame(uint32_t)>& encode,
                                    protocol::Command command, int timeout_ms);

  // ---- States (any thread) --------------------------------------------------------------------------
  // Waits for a state newer than the newest one at the time of the call. Throws UdpException on
  // timeout (options().timeouts.state_ms) or when datagrams of another size arrive. Remembers the
  // state it returns (awaitStandstill counts the travel since a state read while the arm moved).
  RCI::robot::RobotState waitForState();
  // Copies the newest state; false if none arrived yet. Never blocks.
  bool latestState(RCI::robot::RobotState& out) const;
  // Whether the arm stands still (standstill.h), from the states so far. Never blocks.
  Standstill standstill() const;
  // Before a motion or hand guiding is asked for: while the arm is coming to rest on its own (after
  // a stop, a reflex that was recovered, the end of hand guiding) waits for it to stand still, at
  // most kStandstillWaitMs; then goes ahead if it is at rest, else throws MotionException "<call>:
  // the arm is still stopping (joint 2 at 0.12 rad/s); wait until it stands still, then try again".
  // Returns at once otherwise (the controller itself refuses a motion while one runs, during hand
  // guiding or with error bits).
  // Returns how far the arm moved meanwhile -- counted from the state waitForState() last returned
  // when that state was read while the arm still moved (the start a program passes is read just
  // before it asks, and the arm moved on since).
  StandstillWait awaitStandstill(const char* call);
  // The GUI's ring of compact samples: exactly one consumer thread may pop.
  SampleRing& samples() { return *samples_; }
  SessionTiming timing() const;
  // What the real-time thread got (valid once open() returned; empty when closed). Any thread.
  net::RealtimeStatus realtimeStatus() const;
  // The UDP port the states arrive on (0 when closed).
  uint16_t udpPort() const { return udp_port_.load(); }

  // ---- Control (one caller at a time) ------------------------------------------------------------
  // Calls the callback once per received state while the controller reports the motion running,
  // answers each state with the command, and returns when the run ends (see ControlOutcome).
  // The callback must stay alive until this returns.
  // Robot::startMove calls beginMotionHold right before sending StartMove: from then on, until a
  // Control() run takes over, the real-time thread answers every new state with "hold still" (the
  // measured position, no extra torque), so the controller loses no command however long the
  // caller takes to reach Control(). endMotionHold() stops that (refused StartMove, stopMove()).
  void beginMotionHold(ControlKind kind);
  void endMotionHold();
  ControlResult runControl(const JointControl& callback, MissedStates missed = MissedStates::kReplay);
  ControlResult runControl(const CartesianControl& callback, MissedStates missed = MissedStates::kReplay);
  ControlResult runControl(const TorqueControl& callback, MissedStates missed = MissedStates::kReplay);

  // ---- Settings remembered for the API's extensions (Robot::toolFrame(), load(), startMove) ------
  // Any thread: remembered() returns a copy, updateRemembered(f) calls f(Remembered&) and returns
  // its result, both under a mutex (Robot calls on several threads set and read them).
  struct Remembered {
    std::array<double, 16> tool{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    double load_mass = 0;
    std::array<double, 3> load_center{};
    std::array<double, 9> load_inertia{};
    MotionLimits limits;      // setJointLimit, setCartesianLimit (limit_check.h)
    bool move_armed = false;  // startMove() succeeded and no Control()/stopMove() since
    RCI::robot::StartMoveRequest::ControllerMode controller_mode{};
    RCI::robot::StartMoveRequest::MotionGeneratorMode motion_mode{};
  };
  Remembered remembered() const {
    std::lock_guard lock(remembered_mutex_);
    return remembered_;
  }
  template <class F>
  auto updateRemembered(F&& f) {
    std::lock_guard lock(remembered_mutex_);
    return f(remembered_);
  }

  struct Realtime;  // the real-time thread's state (connection_rt.cpp)

 private:
  template <class M>
  static protocol::Command commandOf(const M&) { return M::kCommand; }
  static protocol::Command commandOf(const protocol::EmptyRequest& m) { return m.command; }

  ControlResult runControl(ControlKind kind, const void* callback, MissedStates missed);
  void openLocked();
  void closeLocked();
  void handshake();
  void startRealtimeThread();
  void stopRealtimeThread();  // with lifecycle_ held

  const std::string ip_;
  const uint16_t port_;
  const XmateType type_;
  const SessionOptions options_;
  TcpSession tcp_;
  std::atomic<uint16_t> udp_port_{0};    // written with lifecycle_ held; read by any thread
  std::unique_ptr<Realtime> rt_;         // allocated once, reused by every session
  std::unique_ptr<SampleRing> samples_;  // ~2 MB: on the heap, allocated once
  // Open/close/reconnect are serialised by lifecycle_ (held while the session is set up or torn
  // down; never by the real-time thread). rt_running_ tells other threads, without the lock,
  // whether the real-time thread runs (set after it started, cleared after it was joined).
  mutable std::mutex lifecycle_;
  std::thread thread_;                   // lifecycle_
  std::atomic<bool> rt_running_{false};
  std::atomic<bool> ever_opened_{false};
  mutable std::mutex status_mutex_;      // guards status_ (a copy of what the thread reported)
  net::RealtimeStatus status_;
  mutable std::mutex remembered_mutex_;  // guards remembered_
  Remembered remembered_;
  // How far the arm moved from the state the wait began with (null: it did not wait) and from the
  // state last handed out, if that was read while the arm moved, to newest.
  StandstillWait travelSince(const RCI::robot::RobotState* wait_began, const RCI::robot::RobotState& newest) const;
  mutable std::mutex handed_out_mutex_;  // guards handed_out_
  std::optional<RCI::robot::RobotState> handed_out_;  // what waitForState() last returned
};

}  // namespace xmate::client
