// SPDX-License-Identifier: Apache-2.0
// rci-sim's command line (CLI11): the options, their defaults, and their validation.
#pragma once

#include <array>
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

  // --rsi: a simulated KUKA controller (KRC) running this RSI context instead of the xMate simulator
  // (docs/rsi.md, "The simulated KRC"). The options below need it.
  std::optional<std::string> rsi_context;
  std::string rsi_target_ip;       // --rsi-target HOST:PORT; "" = the Ethernet config's IP_NUMBER
  uint16_t rsi_target_port = 0;    // 0 = the Ethernet config's PORT
  bool rsi_relative = false;       // --rsi-mode relative (RSI_ON(#RELATIVE))
  int cycle_ms = 4;                // --cycle-ms 4|12
  std::optional<std::array<double, 6>> start_joints_deg;  // --start-joints-deg A1,...,A6
  int rsi_restart_pause_ms = 2000;  // --rsi-restart-pause: after RSITimeout or a monitor, RSI_ON again (0: never)
  uint64_t rsi_ipoc_start = 0;      // --rsi-ipoc-start
  std::array<double, 6> external_wrench{};  // --external-wrench FX,FY,FZ,TX,TY,TZ (base frame, at the flange)
  // Fault injection, applied once rsi_faults_after_ms after the start.
  int rsi_drop_answers = 0, rsi_delay_answers = 0, rsi_duplicate_robs = 0, rsi_suspend_ms = 0;
  int rsi_faults_after_ms = 1000;
};

// A wrong command line; the message says which option and what is allowed.
struct UsageError : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

Options parseOptions(int argc, const char* const* argv);
// "HOST:PORT" (IPv4 address or localhost); throws UsageError naming `option`.
void parseHostPort(const std::string& option, const std::string& text, std::string& host, uint16_t& port);
std::string usageText();
// True for 127.x.y.z and "localhost".
bool isLoopbackAddress(const std::string& ip);

}  // namespace rcisim
