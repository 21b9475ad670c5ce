// SPDX-License-Identifier: Apache-2.0
// xmate::Robot's motion calls: startMove (which arms a Control() run), stopMove, and Control() with
// the conversion of how the run ended (client::ControlOutcome) into the API's exceptions.
#include <xmate/robot.h>

#include <algorithm>
#include <cstdio>
#include <stdexcept>
#include <vector>

#include "client/clocked_control.h"
#include "client/connection.h"
#include "client/error_bits.h"
#include "client/refusal_cause.h"
#include "client/robot_responses.h"

namespace xmate {
namespace {

using CM = RCI::robot::StartMoveRequest::ControllerMode;
using MM = RCI::robot::StartMoveRequest::MotionGeneratorMode;
using client::ControlKind;
using client::ControlOutcome;

// The callback type a startMove() pair drives (the issue-3 conventions); false for other pairs.
bool kindOfPair(CM controller, MM motion, ControlKind& kind) {
  if ((controller == CM::kJointPosition || controller == CM::kJointImpedance) && motion == MM::kJointPosition)
    kind = ControlKind::kJoint;
  else if ((controller == CM::kCartesianPosition || controller == CM::kCartesianImpedance) &&
           motion == MM::kCartesianPosition)
    kind = ControlKind::kCartesian;
  else if (controller == CM::kTorque && motion == MM::kIdle)
    kind = ControlKind::kTorque;
  else
    return false;
  return true;
}

const char* controllerModeName(CM m) {
  switch (m) {
    case CM::kJointPosition: return "kJointPosition";
    case CM::kCartesianPosition: return "kCartesianPosition";
    case CM::kJointImpedance: return "kJointImpedance";
    case CM::kCartesianImpedance: return "kCartesianImpedance";
    case CM::kTorque: return "kTorque";
  }
  return "unknown";
}

const char* motionModeName(MM m) {
  switch (m) {
    case MM::kIdle: return "kIdle";
    case MM::kJointPosition: return "kJointPosition";
    case MM::kCartesianPosition: return "kCartesianPosition";
  }
  return "unknown";
}

const char* pairFor(ControlKind kind) {
  switch (kind) {
    case ControlKind::kJoint: return "startMove(kJointPosition or kJointImpedance, kJointPosition)";
    case ControlKind::kCartesian: return "startMove(kCartesianPosition or kCartesianImpedance, kCartesianPosition)";
    case ControlKind::kTorque: return "startMove(kTorque, kIdle)";
  }
  return "startMove";
}

// Where the motion ended. The success rate quoted is the lowest the controller reported during the
// motion (the log's last cycles): once it leaves kMove it reports 1.0, which would hide lost commands.
std::string where(const RCI::robot::RobotState& s, const std::vector<ControlRecord>& log) {
  double lowest = s.control_command_success_rate;
  for (const ControlRecord& r : log)
    if (r.state.robot_mode == RCI::robot::RobotMode::kMove) lowest = std::min(lowest, r.state.control_command_success_rate);
  char buf[200];
  std::snprintf(buf, sizeof buf, "at message_id %llu (robot_mode %s, lowest command success rate %.2f)",
                static_cast<unsigned long long>(s.message_id), client::robotModeName(s.robot_mode), lowest);
  return buf;
}

// A loop stall this long cannot be mistaken for jitter (a healthy loop runs every 1 ms cycle): a few
// commands were missing, and the controller may have stopped because of it.
constexpr double kStallNoteMs = 5.0;

// Explains a stall of the client's own loop during the run ("" if there was none worth naming).
std::string stallNote(const client::ControlResult& r) {
  if (r.longest_stall_ms < kStallNoteMs) return "";
  char buf[420];
  std::snprintf(buf, sizeof buf,
                " The client's real-time loop stalled for %.0f ms (until message_id %llu): no command was sent "
                "meanwhile, and the controller stops a motion after about 15 missing commands in a row (a "
                "stall of more than about 15 ms). Give the loop real-time priority (docs/client.md, \"Real-time "
                "setup\"), check this machine with `rci-cli doctor`, or run on a quieter machine.",
                r.longest_stall_ms, static_cast<unsigned long long>(r.stall_message_id));
  return buf;
}

// States in a row the callback missed that are worth naming when the controller stopped the motion
// (a single lost state is routine on a PC without a real-time kernel).
constexpr uint64_t kLossNoteStates = 5;

// Explains states lost on the way during the run, when no stall of the client's loop explains them.
std::string lossNote(const client::ControlResult& r) {
  if (r.longest_miss < kLossNoteStates || r.longest_stall_ms >= kStallNoteMs) return "";
  char buf[400];
  std::snprintf(buf, sizeof buf,
                " %llu states in a row from the controller never reached this PC (until message_id %llu; %llu "
                "missed in the whole motion), so no command was sent for them; the controller stops a motion after "
                "about 15 missing commands in a row. Check the network between this PC and the controller (a direct "
                "cable, no other traffic); `rci-cli bench loop` counts lost states.",
                static_cast<unsigned long long>(r.longest_miss), static_cast<unsigned long long>(r.miss_message_id),
                static_cast<unsigned long long>(r.states_missed));
  return buf;
}

}  // namespace

void Robot::startMove(CM controller_mode, MM motion_mode) {
  ControlKind kind;
  if (!kindOfPair(controller_mode, motion_mode, kind))
    throw std::invalid_argument(std::string("startMove: the pair (") + controllerModeName(controller_mode) + ", " +
                                motionModeName(motion_mode) +
                                ") is not supported; use (kJointPosition or kJointImpedance, kJointPosition), "
                                "(kCartesianPosition or kCartesianImpedance, kCartesianPosition) or (kTorque, kIdle)");
  connection_->ensureOpen();
  connection_->awaitStandstill("startMove");
  protocol::StartMoveRequestMsg m;
  m.controller_mode = uint8_t(controller_mode);
  m.motion_mode = uint8_t(motion_mode);
  connection_->beginMotionHold(kind);
  try {
    client::requireStartMoveSuccess(
        connection_->request("startMove", m, connection_->options().timeouts.motion_response_ms),
        [this] { return client::refusalCause(*connection_, client::Request::kMotion); });
  } catch (...) {
    connection_->endMotionHold();
    throw;
  }
  connection_->updateRemembered([&](client::Connection::Remembered& r) {
    r.move_armed = true;
    r.controller_mode = controller_mode;
    r.motion_mode = motion_mode;
  });
}

void Robot::stopMove() {
  connection_->ensureOpen();
  connection_->updateRemembered([](client::Connection::Remembered& r) { r.move_armed = false; });
  connection_->endMotionHold();
  client::requireStopMoveSuccess(connection_->request(
      "stopMove", protocol::EmptyRequest{protocol::Command::kStopMove},
      connection_->options().timeouts.motion_response_ms));
}

namespace {

// Ends the controller's motion after the client gave up on it; the error that made it give up is
// what the caller needs to see, so a failure here is not reported.
void stopQuietly(Robot& robot) {
  try {
    robot.stopMove();
  } catch (const std::exception&) {
  }
}

[[noreturn]] void raise(Robot& robot, const client::ControlResult& r) {
  const std::string call = std::string("Control(") + client::toString(r.kind) + ")";
  const auto& s = r.last_state;
  switch (r.outcome) {
    case ControlOutcome::kFinished: break;
    case ControlOutcome::kControllerError:
      throw ControlException(call + ": the controller stopped the motion " + where(s, r.log) + " with error bits " +
                                 client::describeErrors(s.errors) + "." + stallNote(r) + lossNote(r) +
                                 " Then call automaticErrorRecovery().",
                             s.errors, r.log);
    case ControlOutcome::kEndedByController:
      throw ControlException(call + ": the controller ended the motion without error bits " + where(s, r.log) +
                                 ": a guard or emergency stop, or stopMove() from elsewhere; check "
                                 "getSafetyStopState() and start the motion again",
                             s.errors, r.log);
    case ControlOutcome::kNotStarted:
      throw ControlException(call + ": the controller did not start the motion within 1 s of startMove() " +
                                 where(s, r.log) + "; call startMove() again right before Control()",
                             s.errors, r.log);
    case ControlOutcome::kFinishNotAcknowledged:
      stopQuietly(robot);
      throw ControlException(call + ": the controller kept moving for 200 ms after the final command "
                                    "(motion_generation_finished) " + where(s, r.log) + "; the motion was stopped with stopMove()",
                             s.errors, r.log);
    case ControlOutcome::kCallbackThrew:
      stopQuietly(robot);
      std::rethrow_exception(r.exception);
    case ControlOutcome::kInvalidCommand:
      stopQuietly(robot);
      throw std::invalid_argument(client::describeCommandFault(r.kind, r.fault, s.message_id));
    case ControlOutcome::kStateTimeout:
      throw UdpException(call + ": no state from the controller for " +
                         std::to_string(robot.connection().options().timeouts.control_silence_ms) +
                         " ms after message_id " + std::to_string(s.message_id) +
                         ": the controller stopped or the network failed. Check the controller, then reconnect()");
    case ControlOutcome::kWrongLength:
      stopQuietly(robot);
      throw UdpException(call + ": the controller sent a state datagram of " + std::to_string(r.wrong_length) +
                         " bytes instead of 1247: it speaks another RCI protocol version; use a matching client library");
    case ControlOutcome::kSessionClosed:
      throw NetworkException(call + ": the session with the controller was closed during the motion; reconnect()");
  }
  throw ControlException(call + ": unknown outcome", s.errors, r.log);
}

template <class Callback>
void control(Robot& robot, client::Connection& connection, ControlKind kind, const Callback& callback,
             client::MissedStates missed) {
  const std::string call = std::string("Control(") + client::toString(kind) + ")";
  if (!callback) throw std::invalid_argument(call + ": the callback is empty");
  const auto remembered = connection.remembered();  // a copy: other threads may start or stop moves
  ControlKind armed_kind;
  if (!remembered.move_armed)
    throw InvalidOperationException(call + ": no motion was started; call " + pairFor(kind) + " first");
  if (!kindOfPair(remembered.controller_mode, remembered.motion_mode, armed_kind) || armed_kind != kind)
    throw InvalidOperationException(call + ": startMove(" + controllerModeName(remembered.controller_mode) + ", " +
                                    motionModeName(remembered.motion_mode) + ") does not drive a " +
                                    client::toString(kind) + " callback; call " + pairFor(kind) + " first");
  connection.ensureOpen();
  // One Control() per startMove().
  connection.updateRemembered([](client::Connection::Remembered& r) { r.move_armed = false; });
  const client::ControlResult result = connection.runControl(callback, missed);
  if (result.outcome != ControlOutcome::kFinished) raise(robot, result);
}

}  // namespace

void Robot::Control(JointControl callback) {
  control(*this, *connection_, ControlKind::kJoint, callback, client::MissedStates::kReplay);
}
void Robot::Control(CartesianControl callback) {
  control(*this, *connection_, ControlKind::kCartesian, callback, client::MissedStates::kReplay);
}
void Robot::Control(TorqueControl callback) {
  control(*this, *connection_, ControlKind::kTorque, callback, client::MissedStates::kReplay);
}

}  // namespace xmate

namespace xmate::client {

void controlByMessageId(Robot& robot, const JointControl& callback) {
  control(robot, robot.connection(), ControlKind::kJoint, callback, MissedStates::kSkip);
}
void controlByMessageId(Robot& robot, const CartesianControl& callback) {
  control(robot, robot.connection(), ControlKind::kCartesian, callback, MissedStates::kSkip);
}

}  // namespace xmate::client
