// SPDX-License-Identifier: Apache-2.0
// sim::KrcServer: the simulated KRC (krc.h) on the network -- one UDP socket that sends each cycle's
// <Rob> to the PC and receives its <Sen> answers, on a timed thread (every 4 or 12 ms of wall time)
// or in lock-step (one cycle per step() call, for deterministic tests); feeds a simulated F/T sensor.
// rci-sim --rsi runs one. docs/rsi.md, "The simulated KRC".
#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <memory>
#include <string>
#include <thread>

#include "net/realtime.h"
#include "net/udp_socket.h"
#include "rsi/codec.h"
#include "sim/krc.h"

namespace xmate::sim {

class SimulatedFtSensor;

struct KrcServerConfig {
  KrcConfig krc;
  std::string bind_ip = "127.0.0.1";  // the KRC's own socket (its port: bind_port, 0 = a free one)
  uint16_t bind_port = 0;
  std::string target_ip;   // where <Rob> goes: "" = the Ethernet config's IP_NUMBER (must then be an address)
  uint16_t target_port = 0;  // 0 = the Ethernet config's PORT
  // Lock-step: step() -- and the thread start() runs when `lockstep` is set -- waits this long for
  // the answer before the cycle counts it late. With `lockstep` the thread starts the next cycle as
  // soon as the answer is in: the KRC's clock follows the PC's answers, not wall time (cycles
  // without an exchange -- RSI off -- still take cycle_ms of wall time).
  bool lockstep = false;
  int lockstep_timeout_ms = 1000;
  bool realtime = false;  // the timed thread tries SCHED_FIFO and locks its memory (reported, never required)
  int realtime_priority = 80;
  // When set, its wrench follows the arm's external wrench (in the flange frame) every cycle. Not owned.
  SimulatedFtSensor* ft_sensor = nullptr;
};

class KrcServer {
 public:
  // Builds the Krc (throws what Krc throws), binds the socket (throws std::runtime_error naming the
  // address and what to do) and resolves the target (std::runtime_error if it is not an address).
  // Set-up: any thread.
  explicit KrcServer(KrcServerConfig config);
  ~KrcServer();  // stop()
  KrcServer(const KrcServer&) = delete;
  KrcServer& operator=(const KrcServer&) = delete;

  // The timed thread ("rci-krc"): a cycle every cycle_ms of wall time; an answer not in by the next
  // send is late (or, with config.lockstep, one cycle after another as step() does). Any thread, not
  // real-time; not together with step().
  void start();
  void stop();
  bool running() const { return thread_.joinable(); }

  // Lock-step: one cycle on the caller's thread -- send one <Rob> (while RSI is on), wait up to
  // lockstep_timeout_ms for its answer, end the cycle. Returns whether this cycle's answer came in.
  // Not real-time (it waits on the network); never while the timed thread runs.
  bool step();

  // Any thread (the Krc's own functions say which of them may run beside the cycle).
  Krc& krc() { return *krc_; }
  const Krc& krc() const { return *krc_; }
  uint16_t port() const { return port_; }   // the KRC's own port (what the PC sees as the source)
  std::string target() const;               // "IP:PORT" <Rob> goes to (allocates)
  uint64_t sendFailures() const { return send_failures_.load(); }  // lock-free
  net::RealtimeStatus realtimeStatus() const;  // what the timed thread got (empty before it started)

 private:
  // One cycle: <Rob> out (twice on the duplicate fault), answers in until deadline_ns (or until the
  // answer, in lock-step), Krc::endCycle, the F/T sensor fed. Allocation-free.
  bool cycle(int64_t deadline_ns, bool stop_when_answered);
  bool waited_ = false;  // the last cycle() waited for an answer (it sent a <Rob> that needs one)
  void run();

  const KrcServerConfig config_;
  std::unique_ptr<Krc> krc_;
  net::UdpSocket socket_;
  net::Endpoint target_;
  uint16_t port_ = 0;
  std::array<char, rsi::kMaxDatagramBytes + 1> out_{};
  std::array<char, rsi::kMaxDatagramBytes + 1> in_{};
  std::thread thread_;
  std::atomic<bool> quit_{false};
  std::atomic<uint64_t> send_failures_{0};
  net::RealtimeStatus status_;
  std::atomic<bool> status_ready_{false};
};

}  // namespace xmate::sim
