// SPDX-License-Identifier: Apache-2.0
// Shared helpers of the simulator server tests: a started server on a free port, bounded waits
// for a condition, a raw client already in a session, and motion start.
#pragma once

#include <QtTest>

#include <chrono>
#include <functional>
#include <memory>
#include <thread>

#include "raw_client.h"
#include "sim/server.h"

namespace simtest {

inline std::unique_ptr<xmate::sim::Server> startServer(xmate::sim::ServerConfig config = {}) {
  config.bind_ip = "127.0.0.1";
  config.port = 0;
  auto server = std::make_unique<xmate::sim::Server>(std::move(config));
  server->start();
  return server;
}

inline xmate::sim::ServerConfig lockStepConfig(int timeout_ms) {
  xmate::sim::ServerConfig c;
  c.clock = xmate::sim::ClockMode::kLockStep;
  c.lockstep_timeout_ms = timeout_ms;
  return c;
}

// Polls condition until it holds or a generous limit passes (a safety net, not a timing claim).
inline bool eventually(const std::function<bool()>& condition, int limit_ms = 10000) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::milliseconds(limit_ms);
  while (std::chrono::steady_clock::now() < end) {
    if (condition()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  return condition();
}

// A client in a session: handshake done and the first state received.
inline std::unique_ptr<RawClient> connectedClient(const xmate::sim::Server& server) {
  auto client = std::make_unique<RawClient>(server.port());
  if (client->handshake() != 0) throw std::runtime_error("Connect was refused");
  if (!client->receiveState(5000)) throw std::runtime_error("no state after Connect");
  return client;
}

// Powers the motors on and starts a joint-position motion: from now on states want answers.
inline void startJointMotion(RawClient& client) {
  using namespace xmate::protocol;
  using Req = RCI::robot::StartMoveRequest;
  if (client.requestByte(SetMotorPowerRequest{1}) != 0) throw std::runtime_error("SetMotorPower(1) refused");
  const uint8_t status = client.requestByte(StartMoveRequestMsg{uint8_t(Req::ControllerMode::kJointPosition),
                                                                uint8_t(Req::MotionGeneratorMode::kJointPosition)});
  if (status != 0) throw std::runtime_error("StartMove refused with status " + std::to_string(status));
}

}  // namespace simtest
