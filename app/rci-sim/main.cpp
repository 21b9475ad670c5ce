// SPDX-License-Identifier: Apache-2.0
// rci-sim: the simulated xMate controller as a program. Parses the command line, starts the
// server (and the control port if asked), prints one status line, and runs until SIGINT/SIGTERM.
#include <pthread.h>
#include <signal.h>

#include <cstdio>
#include <exception>
#include <iostream>
#include <memory>
#include <string>

#include "net/realtime.h"
#include "options.h"
#include "sim/ft_sensor.h"
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

int run(const rcisim::Options& o) {
  // A headless real-time program: pin all of it in RAM (the cycle thread reports what it got).
  if (o.realtime) {
    if (const std::string refused = xmate::net::lockAllMemory(); !refused.empty())
      std::cerr << "rci-sim: " << refused << '\n';
  }
  const sigset_t stop_signals = blockStopSignals();
  if (!rcisim::isLoopbackAddress(o.bind_ip))
    logLine("warning: listening on " + o.bind_ip + ": anyone on that network can move the simulated robot");

  xmate::sim::Server server(serverConfig(o));
  server.start();
  std::unique_ptr<xmate::sim::ControlPort> control;
  if (o.control_port) {
    control = std::make_unique<xmate::sim::ControlPort>(server, o.control_bind_ip, *o.control_port);
    control->start();
  }

  std::unique_ptr<xmate::sim::SimulatedFtSensor> ft_sensor;
  if (o.ft_sensor_port) {
    xmate::sim::FtSensorConfig ft;
    ft.bind_ip = o.bind_ip;
    ft.port = *o.ft_sensor_port;
    ft_sensor = std::make_unique<xmate::sim::SimulatedFtSensor>(ft);
    ft_sensor->start();
  }

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
