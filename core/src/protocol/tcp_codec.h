// SPDX-License-Identifier: Apache-2.0
// The TCP command channel (docs/protocol.md, "Encoding", "Command codes and payloads"): framing
// (uint16 length + uint32 sequence, big-endian) and every request and response payload.
// A payload always begins with the big-endian uint32 Command code.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "protocol/realtime_codec.h"  // DecodeStatus

namespace xmate::protocol {

enum class Command : uint32_t {
  kConnect = 0, kSetMotorPower = 1, kGetMotorState = 2, kStartMove = 3, kStopMove = 4,
  kSetCartesianLimit = 5, kSetJointLimit = 6, kSetCollisionBehavior = 7, kSetJointImpedance = 8,
  kSetCartesianImpedance = 9, kSetCoor = 10, kSetLoad = 11, kSetCartImpDesiredTau = 12,
  kSetFilters = 13, kSetTorqueFilterCutOffFrequency = 14, kAutomaticErrorRecovery = 15,
  kLoadRobotModel = 16, kSetFcCoor = 17, kEnableVirtualGuide = 18, kSetDO = 19, kGetDIState = 20,
  kStartDrag = 21, kStopDrag = 22, kGetSafetyStopState = 23, kRebootRobot = 24,
  kInvalid = 0xFF,
};
const char* commandName(Command command);
// True for the codes 0..24.
bool isKnownCommand(uint32_t code);

inline constexpr size_t kFrameHeaderSize = 6;      // uint16 length + uint32 sequence
inline constexpr size_t kMaxPayloadSize = 1285;    // LoadRobotModelResponse, the largest message

// ---- Requests (client -> controller) ------------------------------------------------------------
// Each has kCommand; requests without fields are sent with EmptyRequest{command}.
struct EmptyRequest { Command command; };
struct ConnectRequest { static constexpr Command kCommand = Command::kConnect; uint16_t udp_port = 0; };
struct SetMotorPowerRequest { static constexpr Command kCommand = Command::kSetMotorPower; uint8_t state = 0; };
struct StartMoveRequestMsg {
  static constexpr Command kCommand = Command::kStartMove;
  uint8_t controller_mode = 0;  // StartMoveRequest::ControllerMode
  uint8_t motion_mode = 0;      // StartMoveRequest::MotionGeneratorMode
};
struct SetCartesianLimitRequest {
  static constexpr Command kCommand = Command::kSetCartesianLimit;
  std::array<double, 3> size{};
  std::array<double, 16> frame{};
  bool active = false;
};
struct SetJointLimitRequest {  // 117 bytes; the 116-byte form without auto_limit is accepted
  static constexpr Command kCommand = Command::kSetJointLimit;
  std::array<double, 7> upper{};  // deg, as the API takes them
  std::array<double, 7> lower{};
  bool auto_limit = false;
};
struct SetCollisionBehaviorRequest {
  static constexpr Command kCommand = Command::kSetCollisionBehavior;
  std::array<double, 7> thresholds{};
};
struct SetJointImpedanceRequest {
  static constexpr Command kCommand = Command::kSetJointImpedance;
  std::array<double, 7> stiffness{};
};
struct SetCartesianImpedanceRequest {
  static constexpr Command kCommand = Command::kSetCartesianImpedance;
  std::array<double, 6> stiffness{};
};
struct SetCoorRequest { static constexpr Command kCommand = Command::kSetCoor; std::array<double, 16> flange_to_tool{}; };
struct SetLoadRequest {
  static constexpr Command kCommand = Command::kSetLoad;
  double mass = 0;
  std::array<double, 3> center{};
  std::array<double, 9> inertia{};
};
struct SetCartImpDesiredTauRequest {
  static constexpr Command kCommand = Command::kSetCartImpDesiredTau;
  std::array<double, 6> tau{};
};
struct SetFiltersRequest {
  static constexpr Command kCommand = Command::kSetFilters;
  double joint_hz = 0, cartesian_hz = 0, torque_hz = 0;
};
struct SetTorqueFilterCutOffFrequencyRequest {
  static constexpr Command kCommand = Command::kSetTorqueFilterCutOffFrequency;
  double hz = 0;
};
struct SetFcCoorRequest {  // type on the wire: 0 world, 1 tool, 2 path
  static constexpr Command kCommand = Command::kSetFcCoor;
  std::array<double, 16> frame{};
  uint8_t type = 0;
};
struct EnableVirtualGuideRequest {
  static constexpr Command kCommand = Command::kEnableVirtualGuide;
  bool enable = false;
  std::array<double, 6> stiffness{};
};
struct SetDORequest { static constexpr Command kCommand = Command::kSetDO; uint8_t signal = 0; bool state = false; };
struct GetDIStateRequest { static constexpr Command kCommand = Command::kGetDIState; uint8_t signal = 0; };
struct StartDragRequest {  // space 0 joint, 1 Cartesian; type 0 translation, 1 rotation, 2 free
  static constexpr Command kCommand = Command::kStartDrag;
  uint8_t space = 0;
  uint8_t type = 0;
};

// ---- Responses (controller -> client) ---------------------------------------------------------------
// Every response but two is {Command; uint8}: a status for setters, StartMove, StopMove, Connect and
// AutomaticErrorRecovery, the state for GetMotorState and GetSafetyStopState.
struct ByteResponse { Command command = Command::kInvalid; uint8_t value = 0; };
// {Command; uint8 status}, 5 bytes. With status kBusy (simulator extension) 6 more bytes follow:
// the IPv4 address (network byte order) and the TCP port (big-endian) of the client that holds the
// session -- 11 bytes.
struct ConnectResponse {
  static constexpr Command kCommand = Command::kConnect;
  uint8_t status = 0;
  bool has_holder = false;
  std::array<uint8_t, 4> holder_ip{};
  uint16_t holder_port = 0;
};
struct GetDIStateResponse { static constexpr Command kCommand = Command::kGetDIState; uint8_t status = 0; bool state = false; };
struct LoadRobotModelResponse {
  static constexpr Command kCommand = Command::kLoadRobotModel;
  uint8_t status = 0;
  std::array<double, 28> dh{};
  std::array<double, 21> dims{};
  std::array<double, 66> dyn_friction{};
  std::array<double, 45> dyn{};
};

// Generic status values of setter responses.
enum class SetterStatus : uint8_t { kSuccess = 0, kNotPossible = 1, kInvalidArgument = 2 };
// kBusy is a SIMULATOR EXTENSION (docs/protocol.md, "Connect"): rci-sim's session is held by
// another client. A real controller answers only 0 or 1.
enum class ConnectStatus : uint8_t { kSuccess = 0, kIncompatibleLibraryVersion = 1, kBusy = 2 };
enum class StartMoveStatus : uint8_t {
  kSuccess, kMotionStarted, kPreempted, kNotPossible, kStartAtSingularPose, kInvalidArgument,
  kReflexAborted, kEmergencyAborted, kInputErrorAborted, kAborted
};
enum class StopMoveStatus : uint8_t { kSuccess, kNotPossible, kEmergencyAborted, kReflexAborted, kAborted };
enum class ErrorRecoveryStatus : uint8_t {
  kSuccess, kNotPossible, kManualRecoveryRequired, kReflexAborted, kEmergencyAborted, kAborted
};
const char* toString(SetterStatus s);
const char* toString(StartMoveStatus s);
const char* toString(StopMoveStatus s);
const char* toString(ErrorRecoveryStatus s);

// ---- Framing ------------------------------------------------------------------------------------------
struct FrameHeader {
  uint16_t length = 0;    // payload bytes that follow the header
  uint32_t sequence = 0;
};
FrameHeader decodeFrameHeader(const uint8_t (&bytes)[kFrameHeaderSize]);

// A whole frame: header followed by the payload bytes.
using Frame = std::vector<uint8_t>;

// The Command code at the start of a payload (kInvalid if too short or unknown).
Command peekCommand(const uint8_t* payload, size_t size);

// Encoders: header + Command code + fields.
Frame encodeFrame(uint32_t sequence, const EmptyRequest& m);
Frame encodeFrame(uint32_t sequence, const ConnectRequest& m);
Frame encodeFrame(uint32_t sequence, const SetMotorPowerRequest& m);
Frame encodeFrame(uint32_t sequence, const StartMoveRequestMsg& m);
Frame encodeFrame(uint32_t sequence, const SetCartesianLimitRequest& m);
Frame encodeFrame(uint32_t sequence, const SetJointLimitRequest& m);
Frame encodeFrame(uint32_t sequence, const SetCollisionBehaviorRequest& m);
Frame encodeFrame(uint32_t sequence, const SetJointImpedanceRequest& m);
Frame encodeFrame(uint32_t sequence, const SetCartesianImpedanceRequest& m);
Frame encodeFrame(uint32_t sequence, const SetCoorRequest& m);
Frame encodeFrame(uint32_t sequence, const SetLoadRequest& m);
Frame encodeFrame(uint32_t sequence, const SetCartImpDesiredTauRequest& m);
Frame encodeFrame(uint32_t sequence, const SetFiltersRequest& m);
Frame encodeFrame(uint32_t sequence, const SetTorqueFilterCutOffFrequencyRequest& m);
Frame encodeFrame(uint32_t sequence, const SetFcCoorRequest& m);
Frame encodeFrame(uint32_t sequence, const EnableVirtualGuideRequest& m);
Frame encodeFrame(uint32_t sequence, const SetDORequest& m);
Frame encodeFrame(uint32_t sequence, const GetDIStateRequest& m);
Frame encodeFrame(uint32_t sequence, const StartDragRequest& m);
Frame encodeFrame(uint32_t sequence, const ByteResponse& m);
Frame encodeFrame(uint32_t sequence, const ConnectResponse& m);  // 5 bytes; 11 with has_holder
Frame encodeFrame(uint32_t sequence, const GetDIStateResponse& m);
Frame encodeFrame(uint32_t sequence, const LoadRobotModelResponse& m);

// Decoders of a payload (without the frame header). kWrongLength if the size is not the message's
// size; kBadValue if the Command code does not match or a bool is not 0/1.
DecodeStatus decodePayload(const uint8_t* payload, size_t size, EmptyRequest& m);
DecodeStatus decodePayload(const uint8_t* payload, size_t size, ConnectRequest& m);
DecodeStatus decodePayload(const uint8_t* payload, size_t size, SetMotorPowerRequest& m);
DecodeStatus decodePayload(const uint8_t* payload, size_t size, StartMoveRequestMsg& m);
DecodeStatus decodePayload(const uint8_t* payload, size_t size, SetCartesianLimitRequest& m);
DecodeStatus decodePayload(const uint8_t* payload, size_t size, SetJointLimitRequest& m);
DecodeStatus decodePayload(const uint8_t* payload, size_t size, SetCollisionBehaviorRequest& m);
DecodeStatus decodePayload(const uint8_t* payload, size_t size, SetJointImpedanceRequest& m);
DecodeStatus decodePayload(const uint8_t* payload, size_t size, SetCartesianImpedanceRequest& m);
DecodeStatus decodePayload(const uint8_t* payload, size_t size, SetCoorRequest& m);
DecodeStatus decodePayload(const uint8_t* payload, size_t size, SetLoadRequest& m);
DecodeStatus decodePayload(const uint8_t* payload, size_t size, SetCartImpDesiredTauRequest& m);
DecodeStatus decodePayload(const uint8_t* payload, size_t size, SetFiltersRequest& m);
DecodeStatus decodePayload(const uint8_t* payload, size_t size, SetTorqueFilterCutOffFrequencyRequest& m);
DecodeStatus decodePayload(const uint8_t* payload, size_t size, SetFcCoorRequest& m);
DecodeStatus decodePayload(const uint8_t* payload, size_t size, EnableVirtualGuideRequest& m);
DecodeStatus decodePayload(const uint8_t* payload, size_t size, SetDORequest& m);
DecodeStatus decodePayload(const uint8_t* payload, size_t size, GetDIStateRequest& m);
DecodeStatus decodePayload(const uint8_t* payload, size_t size, StartDragRequest& m);
DecodeStatus decodePayload(const uint8_t* payload, size_t size, ByteResponse& m);
// Liberal, as a client must be: any payload of at least 5 bytes starting with the Connect code. The
// holder is read when the status is kBusy and 6 more bytes follow; other trailing bytes are ignored.
DecodeStatus decodePayload(const uint8_t* payload, size_t size, ConnectResponse& m);
DecodeStatus decodePayload(const uint8_t* payload, size_t size, GetDIStateResponse& m);
DecodeStatus decodePayload(const uint8_t* payload, size_t size, LoadRobotModelResponse& m);

}  // namespace xmate::protocol
