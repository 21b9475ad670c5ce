// SPDX-License-Identifier: Apache-2.0
// rci-sim: the simulated xMate controller as a program -- or, with --rsi, the simulated KUKA
// controller (KRC) running an RSI context. Parses the command line, starts the server (and the
// control port or the F/T sensor if asked), prints one status line, and runs until SIGINT/SIGTERM.
#include <pthread.h>
#include <signal.h>
#include <time.h>

#include <cstdio>
#include <exception>
#include <iostream>
#include <memory>
#include <string>

#include "net/realtime.h"
#include "options.h"
#include "sim/ft_sensor.h"
#include "sim/krc_control.h"
#include "sim/krc_server.h"
#include "sim/server.h"
#include "sim/server_control.h"

namespace {

// Called from the server's threads: one write per line so lines do not interleave.
void logLine(const std::string& line) {
  const std::string text = "rci-sim: " + line + "\n";
  std::fwrite(text.data(), 1, text.size(), stderr);
}

xmate::sim::ServerConfig serverConfig(const rcisim::Options& o) {
  xmate::sim::ServerConfig c;
  c.bind_ip = o.bind_ip;
  c.port = o.port;
  c.clock = o.lockstep ? xmate::sim::ClockMode::kLockStep : xmate::sim::ClockMode::kRealTime;
  c.lockstep_timeout_ms = o.lockstep_timeout_ms;
  c.reboot_pause_ms = o.reboot_pause_ms;
  c.connect_timeout_ms = o.connect_timeout_ms;
  c.idle_timeout_ms = o.idle_timeout_ms;
  c.realtime = o.realtime;
  c.sim.type = o.model->type;
  c.sim.do_to_di_loopback = o.loopback_io;
  c.sim.motors_on_at_start = o.motors_on;
  c.log = logLine;
  return c;
}

// Blocks SIGINT and SIGTERM in this thread and every thread started after it; main waits for them.
sigset_t blockStopSignals() {
  sigset_t set;
  sigemptyset(&set);
  sigaddset(&set, SIGINT);
  sigaddset(&set, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &set, nullptr);
  return set;
}

std::unique_ptr<xmate::sim::SimulatedFtSensor> startFtSensor(const rcisim::Options& o) {
  if (!o.ft_sensor_port) return nullptr;
  xmate::sim::FtSensorConfig ft;
  ft.bind_ip = o.bind_ip;
  ft.port = *o.ft_sensor_port;
  auto sensor = std::make_unique<xmate::sim::SimulatedFtSensor>(ft);
  sensor->start();
  return sensor;
}

// Waits for SIGINT or SIGTERM, or until timeout_ms has passed (-1: no limit); the signal or 0.
int waitForStop(const sigset_t& stop_signals, int timeout_ms) {
  if (timeout_ms < 0) {
    int signal_number = 0;
    sigwait(&stop_signals, &signal_number);
    return signal_number;
  }
  const timespec timeout{timeout_ms / 1000, long(timeout_ms % 1000) * 1'000'000};
  const int got = sigtimedwait(&stop_signals, nullptr, &timeout);
  return got > 0 ? got : 0;
}

// --rsi: the simulated KRC on its timed thread, until SIGINT/SIGTERM.
int runRsi(const rcisim::Options& o, const sigset_t& stop_signals) {
  std::unique_ptr<xmate::sim::SimulatedFtSensor> ft_sensor = startFtSensor(o);
  xmate::sim::KrcServerConfig c;
  c.krc.context_path = *o.rsi_context;
  c.krc.model = std::string(o.model->name);
  c.krc.mode = o.rsi_relative ? xmate::rsi::CorrectionMode::kRelative : xmate::rsi::CorrectionMode::kAbsolute;
  c.krc.cycle_ms = o.cycle_ms;
  if (o.start_joints_deg) c.krc.start_deg = *o.start_joints_deg;
  c.krc.ipoc_start = o.rsi_ipoc_start;
  c.krc.restart_pause_ms = o.rsi_restart_pause_ms;
  c.krc.log = logLine;
  c.bind_ip = o.bind_ip;
  c.target_ip = o.rsi_target_ip;
  c.target_port = o.rsi_target_port;
  c.realtime = o.realtime;
  c.lockstep = o.lockstep;
  c.lockstep_timeout_ms = o.lockstep_timeout_ms;
  c.ft_sensor = ft_sensor.get();
  xmate::sim::KrcServer krc(c);
  krc.krc().setExternalWrench(o.external_wrench);
  krc.start();
  std::unique_ptr<xmate::sim::ControlPort> control;
  if (o.control_port) {
    control = std::make_unique<xmate::sim::ControlPort>(
        [&krc](std::string_view line) { return xmate::sim::executeKrcControlLine(krc.krc(), line); }, o.control_bind_ip,
        *o.control_port);
    control->start();
  }

  if (o.print_port) std::cout << krc.port() << '\n';
  std::cout << "rci-sim: " << o.model->display_name << " (KUKA RSI) on " << o.bind_ip << ':' << krc.port()
            << ", sending <Rob> to " << krc.target()
            << (o.lockstep ? " in lock-step (each cycle as soon as its answer is in), cycle "
                           : " every ")
            << o.cycle_ms << " ms, "
            << (o.rsi_relative ? "#RELATIVE" : "#ABSOLUTE") << ", Timeout " << krc.krc().timeoutLimit() << ", context "
            << *o.rsi_context << '\n';
  if (control)
    std::cout << "rci-sim: control port on " << o.control_bind_ip << ':' << control->port() << " (type help)\n";
  if (ft_sensor)
    std::cout << "rci-sim: F/T sensor (Net F/T, RDT) on " << o.bind_ip << ':' << ft_sensor->port()
              << ", reading the arm's external wrench\n";
  std::cout.flush();

  const bool faults = o.rsi_drop_answers || o.rsi_delay_answers || o.rsi_duplicate_robs || o.rsi_suspend_ms;
  int signal_number = waitForStop(stop_signals, faults ? o.rsi_faults_after_ms : -1);
  if (signal_number == 0) {
    xmate::sim::Krc& k = krc.krc();
    if (o.rsi_drop_answers) k.dropAnswers(o.rsi_drop_answers);
    if (o.rsi_delay_answers) k.delayAnswers(o.rsi_delay_answers);
    if (o.rsi_duplicate_robs) k.duplicateRobs(o.rsi_duplicate_robs);
    if (o.rsi_suspend_ms) k.suspendSending(o.rsi_suspend_ms);
    logLine("faults injected: drop " + std::to_string(o.rsi_drop_answers) + " answers, delay " +
            std::to_string(o.rsi_delay_answers) + ", duplicate " + std::to_string(o.rsi_duplicate_robs) +
            " <Rob>, suspend " + std::to_string(o.rsi_suspend_ms) + " ms");
    signal_number = waitForStop(stop_signals, -1);
  }
  logLine(std::string("stopping (") + (signal_number == SIGINT ? "SIGINT" : "SIGTERM") + ")");
  if (control) control->stop();
  krc.stop();
  const xmate::sim::KrcStatus s = krc.krc().status();
  logLine("<Rob> sent " + std::to_string(s.robs_sent) + ", answers used " + std::to_string(s.answers_used) + ", late " +
          std::to_string(s.answers_late) + ", RSITimeouts " + std::to_string(s.timeouts) + ", sessions " +
          std::to_string(s.session));
  return 0;
}

int run(const rcisim::Options& o) {
  // A headless real-time program: pin all of it in RAM (the cycle thread reports what it got).
  if (o.realtime) {
    if (const std::string refused = xmate::net::lockAllMemory(); !refused.empty())
      std::cerr << "rci-sim: " << refused << '\n';
  }
  const sigset_t stop_signals = blockStopSignals();
  if (!rcisim::isLoopbackAddress(o.bind_ip))
    logLine("warning: listening on " + o.bind_ip + ": anyone on that network can move the simulated robot");
  if (o.rsi_context) return runRsi(o, stop_signals);

  xmate::sim::Server server(serverConfig(o));
  server.start();
  std::unique_ptr<xmate::sim::ControlPort> control;
  if (o.control_port) {
    control = std::make_unique<xmate::sim::ControlPort>(server, o.control_bind_ip, *o.control_port);
    control->start();
  }

  std::unique_ptr<xmate::sim::SimulatedFtSensor> ft_sensor = startFtSensor(o);

  if (o.print_port) std::cout << server.port() << '\n';
  const xmate::sim::ServerStatus st = server.status();
  std::cout << "rci-sim: " << o.model->display_name << " on " << o.bind_ip << ':' << server.port() << ", "
            << xmate::sim::toString(st.clock) << ", " << st.realtime << '\n';
  if (control)
    std::cout << "rci-sim: control port on " << o.control_bind_ip << ':' << control->port() << " (type help)\n";
  if (ft_sensor)
    std::cout << "rci-sim: F/T sensor (Net F/T, RDT) on " << o.bind_ip << ':' << ft_sensor->port()
              << ", reading a zero wrench\n";
  std::cout.flush();

  int signal_number = 0;
  sigwait(&stop_signals, &signal_number);
  logLine(std::string("stopping (") + (signal_number == SIGINT ? "SIGINT" : "SIGTERM") + ")");
  if (control) control->stop();
  server.stop();
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  rcisim::Options options;
  try {
    options = rcisim::parseOptions(argc, argv);
  } catch (const rcisim::UsageError& e) {
    std::cerr << "rci-sim: " << e.what() << "\nrun rci-sim --help for the options\n";
    return 2;
  }
  if (options.help) {
    std::cout << rcisim::usageText();
    return 0;
  }
  if (options.version) {
    std::cout << "rci-sim " << RCI_VERSION << '\n';
    return 0;
  }
  try {
    return run(options);
  } catch (const std::exception& e) {
    std::cerr << "rci-sim: " << e.what() << '\n';
    return 1;
  }
}
