// SPDX-License-Identifier: Apache-2.0
// Test harness for sim::Controller: sends TCP requests through handleRequest (encoded exactly as a
// client would) and decodes the responses, and steps the 1 kHz cycle with joint, Cartesian or
// torque commands answering the current state. No sockets.
#pragma once

#include <array>
#include <cstdint>
#include <string>

#include <Eigen/Geometry>

#include "protocol/tcp_codec.h"
#include "sim/controller.h"

namespace xmate::sim::test {

using RCI::robot::RobotCommand;
using RCI::robot::RobotState;
using CM = RCI::robot::StartMoveRequest::ControllerMode;
using MG = RCI::robot::StartMoveRequest::MotionGeneratorMode;

// Command code and first value byte of a response frame (works for unknown codes too).
struct RawResponse {
  uint32_t command = 0;
  uint8_t value = 0;
  uint32_t sequence = 0;
  size_t payload_size = 0;
};
RawResponse parseResponse(const protocol::Frame& frame);

class Harness {
 public:
  explicit Harness(const SimConfig& config = {});

  Controller& controller() { return controller_; }
  const RobotState& state() const { return controller_.state(); }
  SimStatus status() const { return controller_.status(); }

  // A request message (any of tcp_codec.h's request structs) -> the whole response frame.
  template <class Message>
  protocol::Frame send(const Message& message) {
    const protocol::Frame request = protocol::encodeFrame(++sequence_, message);
    return sendRaw(request.data() + protocol::kFrameHeaderSize, request.size() - protocol::kFrameHeaderSize);
  }
  protocol::Frame sendRaw(const uint8_t* payload, size_t size);
  // The status / value byte of a {Command; uint8} response.
  template <class Message>
  uint8_t status(const Message& message) {
    return parseResponse(send(message)).value;
  }
  uint8_t empty(protocol::Command command) { return status(protocol::EmptyRequest{command}); }

  uint8_t setMotorPower(int on) { return status(protocol::SetMotorPowerRequest{uint8_t(on)}); }
  uint8_t startMove(CM controller, MG generator) {
    return status(protocol::StartMoveRequestMsg{uint8_t(controller), uint8_t(generator)});
  }
  uint8_t stopMove() { return empty(protocol::Command::kStopMove); }
  uint8_t recover() { return empty(protocol::Command::kAutomaticErrorRecovery); }
  uint8_t startDrag(int wire_space, int wire_type) {
    return status(protocol::StartDragRequest{uint8_t(wire_space), uint8_t(wire_type)});
  }

  // Power on and let the hold settle for `cycles` ms.
  void powerOnAndSettle(int cycles = 20);
  // Cycles without any command (idle, or every command of a motion lost).
  void idle(int cycles);
  void lose() { controller_.step(nullptr); }

  // One cycle answering the current state.
  void stepJoint(const std::array<double, 7>& q, bool finished = false);
  void stepCartesian(const Eigen::Isometry3d& pose, bool finished = false, bool psi_valid = false, double psi = 0);
  void stepTorque(const std::array<double, 7>& tau, bool finished = false);
  void stepCommand(RobotCommand command);  // message_id is filled in

  bool anyError() const;
  // "bit 3, bit 5" style list of the set error bits, for failure messages.
  std::string errorList() const;

 private:
  Controller controller_;
  uint32_t sequence_ = 0;
};

// Row-major arrays <-> Eigen, for tests.
Eigen::Isometry3d poseOf(const std::array<double, 16>& row_major);
std::array<double, 16> rowMajor(const Eigen::Isometry3d& pose);
Eigen::Matrix<double, 7, 1> vec7(const std::array<double, 7>& a);
std::array<double, 7> arr7(const Eigen::Matrix<double, 7, 1>& v);

}  // namespace xmate::sim::test
