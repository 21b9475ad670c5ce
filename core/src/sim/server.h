// SPDX-License-Identifier: Apache-2.0
// The simulated controller on the network: a sim::Controller wrapped with the RCI sockets (TCP
// command channel, 1 kHz UDP state stream), a real-time or lock-step clock, reboot, and injectable
// scene events and packet faults. rci-sim, the GUI and the tests embed it; docs/simulator.md.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>

#include <xmate/rci_types.h>

#include "sim/controller.h"

namespace xmate::sim {

enum class ClockMode {
  kRealTime,  // one cycle per millisecond of wall time; a late answer counts as lost
  kLockStep,  // during motion, each cycle waits for the client's answer (deterministic tests)
};
const char* toString(ClockMode clock);

struct ServerConfig {
  std::string bind_ip = "127.0.0.1";  // loopback by default: anyone who can reach the port can move the robot
  uint16_t port = 0;                  // TCP command port; 0 picks a free port (rci-sim defaults to 1337)
  ClockMode clock = ClockMode::kRealTime;
  // Lock-step only: wall time to wait for the answer to a state before the cycle counts as lost.
  int lockstep_timeout_ms = 200;
  // After RebootRobot: no connection is accepted for this long, then a fresh controller answers.
  int reboot_pause_ms = 2000;
  // A TCP connection must complete its Connect handshake within this long or it is closed, so that a
  // connection that never sends a request cannot hold the only session. 0: no limit.
  int connect_timeout_ms = 3000;
  // A session whose client has sent no TCP request and no UDP datagram for this long, with no
  // motion or hand guiding running, is silent: it gives way to the next client that sends Connect
  // (it is dropped and logged). Until then it keeps the controller. 0: sessions never give way.
  int idle_timeout_ms = 10000;
  // Try SCHED_FIFO (at realtime_priority) and lock memory (its stack, the process); the outcome is in status().
  bool realtime = false;
  int realtime_priority = 80;
  SimConfig sim;
  // Receives one line per event (session opened or closed, reboot, kill, listen failures).
  // Called from the server's threads; may be empty.
  std::function<void(const std::string&)> log;
};

// Packet faults still waiting to be applied (each counts down as datagrams pass).
struct PendingFaults {
  int drop_states = 0;           // states not sent
  int drop_commands = 0;         // commands discarded on arrival
  int delay_commands = 0;        // commands held back by delay_ms before they count as received
  int delay_ms = 0;
  int reorder_states = 0;        // states sent with each pair swapped
  int corrupt_states = 0;        // states with an impossible bool and enum (the decoder rejects them)
  int wrong_length_states = 0;   // states kWrongLengthDelta bytes short (as from another version)
};

// A random loss pattern for the state stream that keeps running until switched off (a default
// StateLoss is off): about `probability` of the states are lost at random, as single states or, for
// `pair_share` of the losses, two in a row; and every `burst_every_ms` states (ms of streaming) a
// burst of `burst_states` in a row. A sent state always follows a loss, so losses never merge.
// Seeded: the same seed gives the same pattern (docs/simulator.md, "Random state loss").
struct StateLoss {
  double probability = 0;  // 0..0.5 (0.02 = 2 %); the bursts come on top
  double pair_share = 0;   // 0..1 of the random losses
  int burst_states = 0;    // 0 (no bursts) .. kMaxBurstStates
  int burst_every_ms = 0;  // with burst_states: more than burst_states, at most kMaxBurstEveryMs
  uint32_t seed = 1;
  bool active() const { return probability > 0 || burst_states > 0; }
};
inline constexpr double kMaxLossProbability = 0.5;
inline constexpr int kMaxBurstStates = 10'000;
inline constexpr int kMaxBurstEveryMs = 3'600'000;

// Everything the server counted since start().
struct ServerCounters {
  uint64_t cycles = 0;               // controller steps
  uint64_t states_sent = 0;          // RobotState datagrams sent, faulty ones included
  uint64_t states_dropped = 0;       // by dropStates and by the loss pattern
  uint64_t states_lost = 0;          // of those, by the loss pattern (setStateLoss) ...
  uint64_t loss_singles = 0;         // ... in its losses of one state,
  uint64_t loss_pairs = 0;           // of two in a row,
  uint64_t loss_bursts = 0;          // and its bursts
  uint64_t states_reordered = 0;
  uint64_t states_corrupted = 0;
  uint64_t states_wrong_length = 0;
  uint64_t commands_received = 0;    // well-formed RobotCommand datagrams
  uint64_t commands_used = 0;        // answered their state in time and were passed to step()
  uint64_t commands_stale = 0;       // well-formed, but for another state or after their cycle
  uint64_t commands_malformed = 0;   // wrong length or impossible values
  uint64_t commands_lost = 0;        // a state that needed an answer got none in time
  uint64_t commands_dropped = 0;     // discarded by the drop fault
  uint64_t commands_delayed = 0;     // held back by the delay fault
  uint64_t sessions = 0;             // successful Connect handshakes
  uint64_t reboots = 0;
  uint64_t clients_refused = 0;      // told "busy" (or closed) because another client held the session
  uint64_t sessions_dropped = 0;     // closed without Connect in time, or silent and taken over
};

struct ServerStatus {
  bool running = false;     // between start() and stop()
  bool killed = false;      // kill() was called: no stream, no TCP, until stop() + start()
  bool rebooting = false;   // in the pause after RebootRobot
  bool session = false;     // a TCP client is connected
  bool streaming = false;   // states are being sent (after a successful Connect)
  uint16_t port = 0;        // TCP command port
  std::string client;       // UDP endpoint states go to ("127.0.0.1:40000"), empty if none
  ClockMode clock = ClockMode::kRealTime;
  std::string realtime;     // what the cycle thread got: "SCHED_FIFO 80, memory locked" / "normal priority (...)"
  PendingFaults pending;
  StateLoss state_loss;     // the loss pattern in effect (default: off)
  ServerCounters counters;
  SimStatus sim;            // the controller's own snapshot
  std::string last_refusal; // why the controller last refused a TCP request ("" if none yet)
  uint64_t message_id = 0;  // of the newest state
  // message_id of the state just sent whose answer the cycle is waiting for; 0 while no answer is
  // needed. In lock-step the simulator stands still on this state until the answer comes.
  uint64_t awaiting_answer_to = 0;
};

// A wrong-length state is this many bytes shorter than kRobotStateSize.
inline constexpr size_t kWrongLengthDelta = 8;

class Server {
 public:
  explicit Server(ServerConfig config);
  ~Server();  // stop()s
  Server(const Server&) = delete;
  Server& operator=(const Server&) = delete;

  // Creates a fresh controller, binds the TCP port and the UDP socket and starts the threads.
  // After a stop() the same TCP port is bound again (so clients can reconnect to it).
  // Throws std::runtime_error saying what failed (e.g. the port is in use) and what to do.
  void start();
  // Closes every socket and joins the threads. Safe to call twice.
  void stop();
  bool running() const;
  uint16_t port() const;  // the bound TCP port (valid after start())
  const ServerConfig& config() const;

  // ---- Scene (the world around the robot; survives a reboot) ---------------------------------
  // Each call is applied between two cycles and returns once applied (or at once when stopped:
  // then it applies at the next start()). Arguments are validated (std::invalid_argument).
  void setExternalWrench(const std::array<double, 6>& wrench);  // base frame at the TCP, N and Nm
  void setEmergencyStop(bool pressed);
  void setGuardStop(bool active);
  void setDigitalInput(int index, bool level);  // 0..5 = DI0_0..DI1_1
  void setDoToDiLoopback(bool on);
  // What really hangs on the flange (flange frame: kg, m, kg m^2 about the centre of mass,
  // row-major), whatever setLoad told the controller; followConfiguredLoad() undoes it.
  void setActualPayload(double mass, const std::array<double, 3>& center, const std::array<double, 9>& inertia);
  void followConfiguredLoad();
  // Puts the arm at q (rad), at rest (Controller::placeArm: also beyond the limits, for tests of
  // recovery). Unlike the scene, a reboot does not keep it: the fresh controller starts at initial_q.
  void placeArm(const std::array<double, 7>& q);

  // ---- Packet faults (counted in datagrams from the next cycle on) -------------------------------
  void dropStates(int count);
  void dropCommands(int count);
  void delayCommands(int count, int delay_ms);
  void reorderStates(int count);  // rounded up to an even number: pairs are swapped
  void corruptStates(int count);
  void sendWrongLengthStates(int count);
  // Starts the random loss pattern (replacing the one running, its generator seeded afresh); a
  // default StateLoss switches it off. Throws std::invalid_argument naming a value out of range.
  void setStateLoss(const StateLoss& loss);
  // Controller death: stops the stream and the cycle, closes the TCP session abruptly and stops
  // listening (connections are refused) until stop() + start().
  void kill();

  // ---- Observation ------------------------------------------------------------------------------
  ServerStatus status() const;
  RCI::robot::RobotState latestState() const;  // the newest state the controller produced

  struct Impl;

 private:
  std::unique_ptr<Impl> impl_;
};

// A simulator for a client in the same process (the GUI, rci-cli run, rci-cli bench loop): bound to
// loopback on a free port, with the given model and clock. Callers adjust the rest before starting it.
ServerConfig embeddedConfig(XmateType type, ClockMode clock);
// Creates and starts the server; throws std::runtime_error naming the failure and the likely fix.
std::unique_ptr<Server> startEmbedded(ServerConfig config);

}  // namespace xmate::sim
