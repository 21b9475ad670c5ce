// SPDX-License-Identifier: Apache-2.0
// The inside of sim::Server, shared by its three source files: server.cpp (lifecycle, public calls,
// the job queue), server_cycle.cpp (the 1 kHz cycle thread) and server_session.cpp (the TCP thread).
// Ownership: everything under "cycle thread only" is touched by the cycle thread alone, or by a
// caller holding jobs_mutex while the cycle thread is not alive (see runOnCycleThread).
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "net/tcp_socket.h"
#include "net/udp_socket.h"
#include "sim/controller.h"
#include "sim/server.h"
#include "sim/server_faults.h"

namespace xmate::sim {

// The world around the robot: re-applied to the fresh controller after a reboot or a restart.
struct Scene {
  std::array<double, 6> wrench{};
  bool estop = false;
  bool gstop = false;
  std::array<bool, 6> digital_in{};
  bool loopback = false;
  struct Payload {
    double mass = 0;
    std::array<double, 3> center{};
    std::array<double, 9> inertia{};
  };
  std::optional<Payload> actual_payload;  // empty: the payload is whatever setLoad configured
};

// What the cycle thread publishes after every cycle (trivially copyable parts of ServerStatus).
struct Snapshot {
  bool streaming = false;
  bool rebooting = false;
  uint64_t awaiting_answer_to = 0;
  PendingFaults pending;
  StateLoss state_loss;
  ServerCounters counters;
  SimStatus sim;
  RCI::robot::RobotState state;
};

struct Server::Impl {
  explicit Impl(ServerConfig c) : config(std::move(c)) {}

  void log(const std::string& line) const {
    if (config.log) config.log(line);
  }

  const ServerConfig config;

  // ---- Lifecycle (start()/stop() on the caller's thread) -----------------------------------------
  std::mutex lifecycle_mutex;       // serialises start(), stop(), kill()
  std::atomic<bool> running{false};
  std::atomic<uint16_t> bound_port{0};  // kept across stop()/start() so clients can reconnect
  std::atomic<bool> stopping{false};
  std::atomic<bool> killed{false};
  std::thread cycle_thread;
  std::thread tcp_thread;

  // ---- Jobs: (TCP thread, API callers) -> cycle thread, run between two cycles ------------------
  std::mutex jobs_mutex;
  std::condition_variable jobs_cv;  // signalled when a job completes or the cycle thread ends
  std::deque<std::function<void()>> jobs;
  uint64_t jobs_posted = 0;
  uint64_t jobs_done = 0;
  bool cycle_alive = false;         // the cycle thread runs jobs; else callers run them inline

  // ---- Cycle thread only -------------------------------------------------------------------------
  std::unique_ptr<Controller> controller;  // null during the reboot pause
  net::UdpSocket udp;
  bool streaming = false;
  net::Endpoint stream_to;
  Scene scene;
  StateFaults state_faults;
  CommandFaults command_faults;
  ServerCounters counters;
  int64_t reboot_until_ns = 0;

  // ---- Shared flags and published values ---------------------------------------------------------
  std::atomic<bool> rebooting{false};
  std::atomic<uint64_t> reboots_begun{0};  // the TCP thread drops its session when this changes
  std::atomic<bool> session_open{false};
  std::atomic<int64_t> last_client_datagram_ns{0};  // cycle thread: the last UDP datagram that arrived
  std::atomic<uint64_t> clients_refused{0};         // TCP thread (ServerCounters::clients_refused)
  std::atomic<uint64_t> sessions_dropped{0};        // TCP thread (ServerCounters::sessions_dropped)
  mutable std::mutex snapshot_mutex;
  Snapshot snapshot;
  std::string client_text;                 // guarded by snapshot_mutex
  std::string realtime_text;               // guarded by snapshot_mutex
  std::string last_refusal;                // guarded by snapshot_mutex; updated per request

  // Start-up hand-shake: the cycle thread reports its real-time status before start() returns.
  std::mutex startup_mutex;
  std::condition_variable startup_cv;
  bool cycle_started = false;

  // TCP thread: the listener is opened by start() and then owned by the TCP thread.
  net::TcpListener listener;
};

// ---- server.cpp ------------------------------------------------------------------------------------
// Runs job on the cycle thread between two cycles and waits until it ran; an exception it throws
// is rethrown here. When the cycle thread is not alive (not started, killed, stopped), runs it
// here under jobs_mutex instead.
void runOnCycleThread(Server::Impl& s, const std::function<void()>& job);
// Cycle thread: runs every queued job (each outside the lock) and wakes their waiters.
void runQueuedJobs(Server::Impl& s);
// Cycle thread (or inline job): copies the counters, the controller's status and state.
void publishSnapshot(Server::Impl& s);
// Applies the scene to the current controller (after start or reboot).
void applyScene(Server::Impl& s);

// ---- server_cycle.cpp ---------------------------------------------------------------------------------
void runCycleThread(Server::Impl& s);
// Cycle thread (inside a job or between cycles): RebootRobot was accepted. Stops the stream, drops
// the controller and starts the reboot pause; the TCP thread sees reboots_begun change.
void beginReboot(Server::Impl& s);

// ---- server_session.cpp -------------------------------------------------------------------------------
void runTcpThread(Server::Impl& s);
// Cycle thread (inside a job): the client went away. Stops the stream and any motion or drag.
void endSessionOnController(Server::Impl& s);

}  // namespace xmate::sim
