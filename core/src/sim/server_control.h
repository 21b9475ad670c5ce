// SPDX-License-Identifier: Apache-2.0
// rci-sim's control port: a line protocol over TCP for scene events and packet faults, one command
// per line, each answered by one line starting with "ok" or "error" (docs/simulator.md).
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <thread>

#include "net/tcp_socket.h"
#include "sim/server.h"

namespace xmate::sim {

// Executes one command line against the server and returns the answer (without newline):
// "ok ..." or "error <what is wrong>; usage: ...". Never throws.
std::string executeControlLine(Server& server, std::string_view line);

// The command list, as "help" prints it (one line).
std::string controlHelp();

// "running=1 killed=0 ... " -- the status as one line of key=value pairs.
std::string formatStatus(const ServerStatus& status);

// Serves the line protocol on a TCP port, one connection at a time, on its own thread: each line
// goes to `execute` (the simulated xMate's commands, or the simulated KRC's: krc_control.h).
class ControlPort {
 public:
  using Execute = std::function<std::string(std::string_view line)>;  // called on the port's thread
  ControlPort(Server& server, std::string bind_ip, uint16_t port);
  ControlPort(Execute execute, std::string bind_ip, uint16_t port);
  ~ControlPort();  // stop()s
  ControlPort(const ControlPort&) = delete;
  ControlPort& operator=(const ControlPort&) = delete;

  // Binds (port 0 picks a free one) and starts the thread. Throws std::runtime_error if the port
  // cannot be bound, saying which and why.
  void start();
  void stop();
  uint16_t port() const { return port_; }

 private:
  void run();
  void serve(net::TcpConnection& conn);

  Execute execute_;
  std::string bind_ip_;
  uint16_t port_;
  net::TcpListener listener_;
  std::atomic<bool> stopping_{false};
  std::thread thread_;
};

}  // namespace xmate::sim
