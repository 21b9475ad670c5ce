// SPDX-License-Identifier: Apache-2.0
// Opening and closing one session's link (robot client + embedded simulator) and the idle poll.
#include "session/session_link.h"

#include <chrono>
#include <stdexcept>
#include <thread>
#include <utility>

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

}  // namespace

std::unique_ptr<Link> openLink(const SessionTarget& target) {
  auto link = std::make_unique<Link>();
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
  } catch (const std::exception& e) {
    link->robot.reset();
    if (link->server) link->server->stop();
    throw std::runtime_error(robotFailure(target, e));
  }
  return link;
}

bool reconnectLink(Link& link) {
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
  bool joined = true;
  if (link.motions) joined = link.motions->stop(kWorkerEndWait) && joined;
  if (link.commands) joined = link.commands->stop(kWorkerEndWait) && joined;
  if (!joined) return false;
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

std::array<double, 7> externalJointTorques(xmate::XmateModel& model, const std::array<double, 7>& q,
                                           const std::array<double, 6>& wrench) {
  const std::array<double, 42> jacobian = model.Jacobian(q);  // 6x7 row-major
  std::array<double, 7> tau{};
  for (size_t joint = 0; joint < 7; ++joint)
    for (size_t row = 0; row < 6; ++row) tau[joint] += jacobian[row * 7 + joint] * wrench[row];
  return tau;
}

}  // namespace rci::ui
