// SPDX-License-Identifier: Apache-2.0
// Helpers of client_test_support.h.
#include "client_test_support.h"

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <thread>

#include <xmate/move.h>

#include "net/tcp_socket.h"

namespace client_test {

using namespace xmate;

std::unique_ptr<sim::Server> startSim(const SimOptions& o) {
  sim::ServerConfig c;
  c.bind_ip = "127.0.0.1";
  c.port = 0;
  c.clock = o.clock;
  c.lockstep_timeout_ms = o.lockstep_timeout_ms;
  c.reboot_pause_ms = o.reboot_pause_ms;
  c.sim.type = o.type;
  c.sim.motors_on_at_start = o.motors_on;
  c.sim.do_to_di_loopback = o.loopback_io;
  c.sim.reject_connect_as_incompatible = o.reject_connect;
  c.sim.instability_threshold = o.instability_threshold;
  auto server = std::make_unique<sim::Server>(std::move(c));
  server->start();
  return server;
}

std::unique_ptr<Robot> robotFor(const sim::Server& server, XmateType type) {
  return std::make_unique<Robot>("127.0.0.1", server.port(), type);
}

uint16_t unusedPort() {
  net::TcpListener listener;
  listener.listen("127.0.0.1", 0);
  const uint16_t port = listener.localPort();
  listener.close();
  return port;
}

bool eventually(const std::function<bool()>& condition, int limit_ms) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::milliseconds(limit_ms);
  while (std::chrono::steady_clock::now() < end) {
    if (condition()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  return condition();
}

DuringMotion::DuringMotion(sim::Server& server, std::function<void()> action, int after_ms) {
  thread_ = std::thread([&server, action = std::move(action), after_ms, fired = fired_] {
    if (!eventually([&] { return server.status().sim.motion_active; })) return;
    std::this_thread::sleep_for(std::chrono::milliseconds(after_ms));
    action();
    *fired = true;
  });
}

DuringMotion::~DuringMotion() {
  if (thread_.joinable()) thread_.join();
}

void whenReady(const std::function<void()>& call) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(5);
  for (;;) {
    try {
      call();
      return;
    } catch (const CommandException&) {
      if (std::chrono::steady_clock::now() > end) throw;
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
  }
}

void startMoveWhenReady(Robot& robot, RCI::robot::StartMoveRequest::ControllerMode controller_mode,
                        RCI::robot::StartMoveRequest::MotionGeneratorMode motion_mode) {
  whenReady([&] { robot.startMove(controller_mode, motion_mode); });
}

bool MachineStalls::excuse(const std::string& failure, double injected_ms) {
  bool machine = failure.find("no state from the controller for") != std::string::npos;
  const std::string stalled = "real-time loop stalled for ";
  const size_t at = failure.find(stalled);
  if (at != std::string::npos && failure.find("kInstabilityDetection") != std::string::npos) {
    const double ms = std::strtod(failure.c_str() + at + stalled.size(), nullptr);
    machine = machine || ms >= injected_ms + kMachineStallMarginMs;
  }
  if (!machine) return false;
  if (count_++ == 0) first_ = failure;
  return true;
}

std::string MachineStalls::summary() const {
  return "the machine stalled the client's real-time thread " + std::to_string(count_) +
         " times in this test (budget " + std::to_string(budget_) +
         "): it says nothing about the library on this machine; rerun on a quieter one. The first: " + first_;
}

std::string excusingMachineStalls(Robot& robot, MachineStalls& stalls, double injected_ms,
                                  const std::function<std::string()>& attempt) {
  const std::array<double, 7> began = robot.receiveRobotState().q;
  auto goBack = [&]() -> std::string {  // recover and return; "" or what went wrong
    try {
      whenReady([&] { robot.automaticErrorRecovery(); });
      eventually([&] { return !anyError(robot.receiveRobotState()); }, 3000);
      whenReady([&] { MOVEJ(0.3, robot.receiveRobotState().q, began, robot); });
    } catch (const std::exception& e) {
      return e.what();
    }
    return {};
  };
  for (;;) {
    const std::string failure = attempt();
    if (failure.empty() || !stalls.excuse(failure, injected_ms) || stalls.exhausted()) return failure;
    for (;;) {  // the way back may be stopped by the machine too
      const std::string back = goBack();
      if (back.empty()) break;
      if (!stalls.excuse(back) || stalls.exhausted()) return "returning after a stall of the machine: " + back;
    }
  }
}

JointControl holdStill(int cycles, int* calls) {
  auto count = std::make_shared<int>(0);
  auto start = std::make_shared<std::array<double, 7>>();
  return [=](RCI::robot::RobotState s) -> JointPositions {
    if (*count == 0) *start = s.q;
    ++*count;
    if (calls) *calls = *count;
    JointPositions out{*start, false};
    return *count >= cycles ? MotionFinished(out) : out;
  };
}

void smoothJointMove(Robot& robot, int joint, double delta, double seconds) {
  auto first = std::make_shared<bool>(true);
  auto start = std::make_shared<std::array<double, 7>>();
  auto id0 = std::make_shared<uint64_t>(0);
  startMoveWhenReady(robot, RCI::robot::StartMoveRequest::ControllerMode::kJointPosition,
                     RCI::robot::StartMoveRequest::MotionGeneratorMode::kJointPosition);
  robot.Control(JointControl([=](RCI::robot::RobotState s) -> JointPositions {
    if (*first) {
      *first = false;
      *start = s.q;
      *id0 = s.message_id - 1;
    }
    const double t = double(s.message_id - *id0) * 1e-3;
    const double x = std::min(1.0, t / seconds);
    // 7th-order smoothstep: zero velocity, acceleration and jerk at both ends.
    const double shape = x * x * x * x * (35 - 84 * x + 70 * x * x - 20 * x * x * x);
    JointPositions out{*start, false};
    out.q[joint] += delta * shape;
    return x >= 1.0 ? MotionFinished(out) : out;
  }));
}

}  // namespace client_test
