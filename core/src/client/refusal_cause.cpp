// SPDX-License-Identifier: Apache-2.0
// refusalCause (refusal_cause.h): the causes a controller refuses motions for, checked one by one
// against the state stream and two TCP queries.
#include "client/refusal_cause.h"

#include <xmate/exception.h>

#include "client/connection.h"
#include "client/error_bits.h"
#include "client/robot_responses.h"
#include "protocol/tcp_codec.h"

namespace xmate::client {
namespace {

using RCI::robot::RobotMode;

// getSafetyStopState's wire value (0 none, 1 ESTOP, 2 GSTOP); -1 if it could not be read.
int safetyStop(Connection& c) {
  try {
    return byteValue("getSafetyStopState",
                     c.request("getSafetyStopState", protocol::EmptyRequest{protocol::Command::kGetSafetyStopState},
                               c.options().timeouts.response_ms));
  } catch (const XmateException&) {
    return -1;
  }
}

// getMotorState's value (0 off, 1 on); -1 if it could not be read.
int motorState(Connection& c) {
  try {
    return byteValue("getMotorState", c.request("getMotorState", protocol::EmptyRequest{protocol::Command::kGetMotorState},
                                                  c.options().timeouts.response_ms));
  } catch (const XmateException&) {
    return -1;
  }
}

}  // namespace

std::string refusalCause(Connection& connection, Request request) {
  RCI::robot::RobotState s;
  const bool have_state = connection.latestState(s);
  if (have_state && anyError(s.errors))
    return "; error bits are set (" + describeErrors(s.errors) + "): call automaticErrorRecovery() first";
  switch (safetyStop(connection)) {
    case 1: return "; the emergency stop is pressed: release it, then call automaticErrorRecovery()";
    case 2: return "; a guard stop is active: release it (close the guard, reset the safety input)";
    default: break;
  }
  const bool moves = request == Request::kMotion || request == Request::kHandGuiding;
  if (moves && motorState(connection) == 0) return "; the motors are off: call setMotorPower(1) first";
  if (!have_state) return "; the controller gave no reason and no state has arrived yet to tell why";
  if (s.robot_mode == RobotMode::kGuiding)
    return request == Request::kSetting ? "; hand guiding is on, and settings cannot change meanwhile: call stopDrag() first"
                                        : "; hand guiding is on: call stopDrag() first";
  if (s.robot_mode == RobotMode::kMove) {
    if (request == Request::kMotion)
      return "; a motion is already running (from another thread or program): wait for its end or call stopMove()";
    if (request == Request::kSetting)
      return "; a motion is running, and settings cannot change meanwhile: set it before startMove() or after the motion";
    return "; a motion is running: wait for its end or call stopMove() first";
  }
  const Standstill still = connection.standstill();
  if (moves && still.known && !still.still) return "; " + stillStoppingText(still) + ": wait until it stands still";
  return std::string("; the controller gave no reason the client can see (robot mode ") + robotModeName(s.robot_mode) +
         (moves ? ", no error bits, no safety stop, motors on, the arm at rest)"
                : ", no error bits, no safety stop, no motion or hand guiding running)");
}

}  // namespace xmate::client
