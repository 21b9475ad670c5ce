// SPDX-License-Identifier: Apache-2.0
// Opening and closing one session's link (an xMate's robot client + embedded simulator, or a
// KUKA's RSI arm + F/T sensor + simulated KRC) and the idle poll.
#include "session/session_link.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <thread>
#include <utility>

#include "arm/rci_arm.h"
#include "model/resource_locator.h"
#include "net/host_port.h"
#include "rsi/config.h"

namespace rci::ui {
namespace {

std::unique_ptr<xmate::sim::Server> startSimulator(const SessionTarget& target) {
  auto config = xmate::sim::embeddedConfig(
      target.type, target.lockstep ? xmate::sim::ClockMode::kLockStep : xmate::sim::ClockMode::kRealTime);
  config.sim.do_to_di_loopback = target.loopback;
  return xmate::sim::startEmbedded(std::move(config));
}

std::string robotFailure(const SessionTarget& target, const std::exception& e) {
  std::string what = e.what();
  if (target.kind == SessionTarget::Kind::kSimulator) return "Could not connect to the built-in simulator: " + what;
  std::string message = "Could not connect to the robot at " + target.host.toStdString() + ":" +
                        std::to_string(target.port) + ": " + what;
  if (what.find("check") == std::string::npos && what.find("Check") == std::string::npos)
    message += ". Check that the controller is switched on and reachable from this PC (ping it), that the address "
               "and port are right (xmate.ini), and that no other program holds the RCI session.";
  return message;
}

// The RSI context the KUKA target runs: the one given, the sample for the built-in simulator, or
// the one beside the Ethernet config that names it.
std::string kukaContext(const SessionTarget& target) {
  if (!target.rsi_context.isEmpty()) return target.rsi_context.toStdString();
  if (target.kind == SessionTarget::Kind::kKukaSimulator)
    return (xmate::model::dataDirectory() / "resources/rsi/rci_replay.rsi.xml").string();
  const std::string config = target.rsi_config.toStdString();
  const std::vector<std::string> found = xmate::rsi::contextsNaming(config);
  if (found.size() == 1) return found.front();
  throw std::runtime_error(
      (found.empty() ? "No RSI context (NAME.rsi.xml) beside " + config + " names it"
                     : std::to_string(found.size()) + " RSI contexts beside " + config + " name it") +
      ". Copy the context the robot runs (from the controller's C:\\KRC\\ROBOTER\\Config\\User\\Common\\SensorInterface) "
      "next to the Ethernet config and connect again.");
}

// "HOST" or "HOST:PORT" of an F/T sensor.
xmate::ft::NetFtOptions sensorOptions(const QString& address) {
  xmate::net::HostPort split;
  if (xmate::net::splitHostPort(address.trimmed().toStdString(), xmate::ft::kDefaultPort, split) !=
      xmate::net::HostPortProblem::kNone)
    throw std::runtime_error("The F/T sensor address \"" + address.toStdString() +
                             "\" is not HOST or HOST:PORT with a port from 1 to 65535 (RDT port 49152).");
  xmate::ft::NetFtOptions options;
  options.host = split.host;
  options.port = split.port;
  return options;
}

// Reads the RSI files, starts listening; for the built-in simulator also the simulated sensor and
// KRC (sending to the port the arm listens on).
void openKuka(Link& link, const SessionTarget& target) {
  const bool simulated = target.kind == SessionTarget::Kind::kKukaSimulator;
  xmate::arm::RsiArmConfig config;
  config.model = target.kuka_model.toStdString();
  config.context_path = kukaContext(target);
  config.ethernet_config_path = simulated ? std::string() : target.rsi_config.toStdString();
  if (simulated) {
    config.link.bind_ip = "127.0.0.1";
    config.link.port = 0;          // a free port
    config.link.silence_ms = 1000;  // a loaded PC may pause the simulated KRC; only its own faults are silence
  }
  link.rsi = std::make_unique<xmate::arm::RsiArm>(config);
  link.rsi->start();
  link.arm = link.rsi.get();
  if (simulated) {
    xmate::sim::FtSensorConfig sensor;
    sensor.port = 0;
    link.ft_simulator = std::make_unique<xmate::sim::SimulatedFtSensor>(sensor);
    link.ft_simulator->start();
    xmate::sim::KrcServerConfig krc;
    krc.krc.context_path = config.context_path;
    krc.krc.model = config.model;
    krc.target_ip = "127.0.0.1";
    krc.target_port = link.rsi->link().port();
    krc.ft_sensor = link.ft_simulator.get();
    link.krc = std::make_unique<xmate::sim::KrcServer>(krc);
    link.krc->start();
    xmate::ft::NetFtOptions options;
    options.host = "127.0.0.1";
    options.port = link.ft_simulator->port();
    link.ft = std::make_unique<xmate::ft::NetFtClient>(options);
  } else if (!target.ft_sensor.trimmed().isEmpty()) {
    link.ft = std::make_unique<xmate::ft::NetFtClient>(sensorOptions(target.ft_sensor));
  }
  if (link.ft) link.ft->start();
}

void stopKuka(Link& link) {
  if (link.krc) link.krc->stop();
  if (link.rsi) link.rsi->stop();
  if (link.ft) link.ft->stop();
  if (link.ft_simulator) link.ft_simulator->stop();
}

std::string kukaFailure(const SessionTarget& target, const std::exception& e) {
  if (target.kind == SessionTarget::Kind::kKukaSimulator)
    return std::string("Could not start the built-in KUKA simulator: ") + e.what();
  return "Could not listen for the KUKA robot (" + target.rsi_config.toStdString() + "): " + e.what();
}

}  // namespace

std::unique_ptr<Link> openLink(const SessionTarget& target) {
  auto link = std::make_unique<Link>();
  link->target = target;
  if (target.isKuka()) {
    try {
      openKuka(*link, target);
    } catch (const std::exception& e) {
      stopKuka(*link);
      throw std::runtime_error(kukaFailure(target, e));
    }
    return link;
  }
  link->target = target;
  std::string host = target.host.toStdString();
  uint16_t port = target.port;
  if (target.kind == SessionTarget::Kind::kSimulator) {
    link->server = startSimulator(target);
    host = "127.0.0.1";
    port = link->server->port();
  }
  try {
    link->robot = std::make_unique<xmate::Robot>(host, port, target.type);
    link->robot->connect();
    link->model = std::make_unique<xmate::XmateModel>(link->robot.get(), target.type);
    link->rci_arm = std::make_unique<xmate::arm::RciArm>(*link->robot);
    link->arm = link->rci_arm.get();
  } catch (const std::exception& e) {
    link->robot.reset();
    if (link->server) link->server->stop();
    throw std::runtime_error(robotFailure(target, e));
  }
  return link;
}

bool reconnectLink(Link& link) {
  if (!link.robot) return false;  // RSI starts again by itself: the RSI arm counts a new session
  using namespace std::chrono;
  const bool simulated = link.server != nullptr;
  const auto deadline = steady_clock::now() + (simulated ? seconds(10) : seconds(60));
  while (!link.closing.load() && steady_clock::now() < deadline) {
    if (simulated && link.server->status().killed) return false;
    const bool waiting = simulated && link.server->status().rebooting;
    if (!waiting && link.robot->reconnect()) return true;
    std::this_thread::sleep_for(simulated ? milliseconds(200) : milliseconds(1000));
  }
  return false;
}

bool shutdownLink(Link& link) {
  link.closing.store(true);
  link.motion.stop.store(true);
  // 1. The motion stops by itself (a smooth ramp down) once it sees its token.
  const bool motion_ended = !link.motions || link.motions->waitIdle(kMotionStopWait);
  // 2. Not within the wait (a job that does not poll its token, a stalled robot): StopMove.
  if (!motion_ended && link.robot) {
    try {
      link.robot->stopMove();
    } catch (const std::exception&) {
      // The controller may be gone already; closing below ends the run anyway.
    }
  }
  // 3. The simulator and the connection close under any job still running: Control() returns
  // kSessionClosed, TCP requests fail fast instead of waiting for their timeouts.
  if (link.server) link.server->stop();
  if (link.robot) link.robot->connection().close();
  stopKuka(link);  // a streamed KUKA motion ends: the robot stops sending
  bool joined = true;
  if (link.motions) joined = link.motions->stop(kWorkerEndWait) && joined;
  if (link.commands) joined = link.commands->stop(kWorkerEndWait) && joined;
  if (!joined) return false;
  link.arm = nullptr;
  link.rci_arm.reset();
  link.robot.reset();
  return true;
}

PollResult pollRobot(xmate::Robot& robot) {
  PollResult result;
  try {
    result.motor_state = robot.getMotorState();
    result.safety_stop = robot.getSafetyStopState();
    for (int i = 0; i < 6; ++i)
      result.digital_in[size_t(i)] = robot.getDI(static_cast<RCI::robot::DISIGNAL>(i));
    result.tool = robot.toolFrame();
    result.ok = true;
  } catch (const std::exception&) {
    result.ok = false;  // the tick's watchdog reports a controller that stopped answering
  }
  return result;
}

PollResult pollArm(xmate::arm::Arm& arm) {
  PollResult result;
  try {
    const size_t inputs = std::min<size_t>(arm.inputNames().size(), 64);
    for (size_t i = 0; i < inputs; ++i)
      if (arm.input(i)) result.kuka_inputs |= uint64_t{1} << i;
    result.ok = true;
  } catch (const std::exception&) {
    result.ok = false;  // no <Rob> yet: the inputs are unknown
  }
  return result;
}

std::array<double, 7> externalJointTorques(xmate::XmateModel& model, const std::array<double, 7>& q,
                                           const std::array<double, 6>& wrench) {
  const std::array<double, 42> jacobian = model.Jacobian(q);  // 6x7 row-major
  std::array<double, 7> tau{};
  for (size_t joint = 0; joint < 7; ++joint)
    for (size_t row = 0; row < 6; ++row) tau[joint] += jacobian[row * 7 + joint] * wrench[row];
  return tau;
}

}  // namespace rci::ui
