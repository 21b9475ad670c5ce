// SPDX-License-Identifier: Apache-2.0
// rci-sim's command line (CLI11): the options, their defaults, and their validation.
#pragma once

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>

#include "model/robot_spec.h"

namespace rcisim {

struct Options {
  const xmate::model::RobotSpec* model = nullptr;  // --model (default xmate7_pro)
  std::string bind_ip = "127.0.0.1";
  uint16_t port = 1337;
  bool lockstep = false;
  int lockstep_timeout_ms = 200;
  std::optional<uint16_t> control_port;
  std::string control_bind_ip = "127.0.0.1";
  std::optional<uint16_t> ft_sensor_port;  // --ft-sensor: serve a simulated ATI Net F/T sensor (RDT)
  bool loopback_io = false;
  bool motors_on = false;
  bool print_port = false;
  bool realtime = true;
  int reboot_pause_ms = 2000;
  int connect_timeout_ms = 3000;  // a connection must send Connect within this (0: no limit)
  int idle_timeout_ms = 10000;    // a silent session gives way to a new client after this (0: never)
  bool help = false;
  bool version = false;  // --version: print "rci-sim VERSION" and exit
};

// A wrong command line; the message says which option and what is allowed.
struct UsageError : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

Options parseOptions(int argc, const char* const* argv);
std::string usageText();
// True for 127.x.y.z and "localhost".
bool isLoopbackAddress(const std::string& ip);

}  // namespace rcisim
