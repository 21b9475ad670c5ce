// SPDX-License-Identifier: Apache-2.0
// Decoding of the controller's status responses into return values and exceptions.
#include "client/robot_responses.h"

#include <xmate/exception.h>

#include "protocol/tcp_codec.h"

namespace xmate::client {
namespace {

[[noreturn]] void unknownStatus(const char* call, uint8_t value) {
  throw ProtocolException(std::string(call) + ": the controller answered with unknown status " +
                          std::to_string(value) + "; it speaks another protocol version");
}

[[noreturn]] void refused(const char* call, const char* status, const std::string& hint) {
  throw CommandException(std::string(call) + ": the controller refused: " + status + hint);
}

}  // namespace

uint8_t byteValue(const char* call, const std::vector<uint8_t>& payload) {
  protocol::ByteResponse response;
  if (protocol::decodePayload(payload.data(), payload.size(), response) != protocol::DecodeStatus::kOk)
    throw ProtocolException(std::string(call) + ": the controller's response has " + std::to_string(payload.size()) +
                            " bytes where 5 were expected; it speaks another protocol version");
  return response.value;
}

void requireSetterSuccess(const char* call, const std::vector<uint8_t>& payload, const char* hint) {
  const uint8_t value = byteValue(call, payload);
  if (value > uint8_t(protocol::SetterStatus::kInvalidArgument)) unknownStatus(call, value);
  const auto status = protocol::SetterStatus(value);
  if (status != protocol::SetterStatus::kSuccess) refused(call, protocol::toString(status), hint);
}

void requireSetterSuccess(const char* call, const std::vector<uint8_t>& payload, const RefusalCause& not_possible) {
  const uint8_t value = byteValue(call, payload);
  if (value > uint8_t(protocol::SetterStatus::kInvalidArgument)) unknownStatus(call, value);
  const auto status = protocol::SetterStatus(value);
  if (status == protocol::SetterStatus::kSuccess) return;
  refused(call, protocol::toString(status), status == protocol::SetterStatus::kNotPossible ? not_possible() : "");
}

void requireStartMoveSuccess(const std::vector<uint8_t>& payload, const RefusalCause& not_possible) {
  const uint8_t value = byteValue("startMove", payload);
  if (value > uint8_t(protocol::StartMoveStatus::kAborted)) unknownStatus("startMove", value);
  using S = protocol::StartMoveStatus;
  const auto status = S(value);
  if (status == S::kSuccess || status == S::kMotionStarted) return;
  std::string hint;
  switch (status) {
    case S::kNotPossible: hint = not_possible(); break;
    case S::kReflexAborted: hint = "; error bits are set: call automaticErrorRecovery() first"; break;
    case S::kEmergencyAborted: hint = "; release the emergency stop, then automaticErrorRecovery()"; break;
    case S::kInvalidArgument:
      hint = "; valid pairs: (kJointPosition or kJointImpedance, kJointPosition), "
             "(kCartesianPosition or kCartesianImpedance, kCartesianPosition), (kTorque, kIdle)";
      break;
    case S::kStartAtSingularPose: hint = "; move the robot away from the singular pose in joint space first"; break;
    default: break;
  }
  refused("startMove", protocol::toString(status), hint);
}

void requireStopMoveSuccess(const std::vector<uint8_t>& payload) {
  const uint8_t value = byteValue("stopMove", payload);
  if (value > uint8_t(protocol::StopMoveStatus::kAborted)) unknownStatus("stopMove", value);
  const auto status = protocol::StopMoveStatus(value);
  if (status != protocol::StopMoveStatus::kSuccess) refused("stopMove", protocol::toString(status), "");
}

void requireRecoverySuccess(const std::vector<uint8_t>& payload) {
  const uint8_t value = byteValue("automaticErrorRecovery", payload);
  if (value > uint8_t(protocol::ErrorRecoveryStatus::kAborted)) unknownStatus("automaticErrorRecovery", value);
  const auto status = protocol::ErrorRecoveryStatus(value);
  if (status != protocol::ErrorRecoveryStatus::kSuccess)
    refused("automaticErrorRecovery", protocol::toString(status), "");
}

bool digitalInputLevel(const std::vector<uint8_t>& payload) {
  protocol::GetDIStateResponse response;
  if (protocol::decodePayload(payload.data(), payload.size(), response) != protocol::DecodeStatus::kOk)
    throw ProtocolException("getDI: the controller's response has " + std::to_string(payload.size()) +
                            " bytes where 6 were expected; it speaks another protocol version");
  if (response.status > uint8_t(protocol::SetterStatus::kInvalidArgument)) unknownStatus("getDI", response.status);
  const auto status = protocol::SetterStatus(response.status);
  if (status != protocol::SetterStatus::kSuccess) refused("getDI", protocol::toString(status), "");
  return response.state;
}

}  // namespace xmate::client
