// SPDX-License-Identifier: Apache-2.0
// Field order of every TCP message, written once (fields()) and used for both directions.
#include "protocol/tcp_codec.h"

#include <tuple>
#include <type_traits>

#include "protocol/byte_io.h"

namespace xmate::protocol {
namespace {

// The wire order of each message's fields (after the Command code), for const and non-const use.
#define RCI_FIELDS(Type, ...)                                                       \
  [[maybe_unused]] auto fields(Type& m) { return std::tie(__VA_ARGS__); }           \
  [[maybe_unused]] auto fields(const Type& m) { return std::tie(__VA_ARGS__); }

RCI_FIELDS(ConnectRequest, m.udp_port)
RCI_FIELDS(SetMotorPowerRequest, m.state)
RCI_FIELDS(StartMoveRequestMsg, m.controller_mode, m.motion_mode)
RCI_FIELDS(SetCartesianLimitRequest, m.size, m.frame, m.active)
RCI_FIELDS(SetJointLimitRequest, m.upper, m.lower, m.auto_limit)
RCI_FIELDS(SetCollisionBehaviorRequest, m.thresholds)
RCI_FIELDS(SetJointImpedanceRequest, m.stiffness)
RCI_FIELDS(SetCartesianImpedanceRequest, m.stiffness)
RCI_FIELDS(SetCoorRequest, m.flange_to_tool)
RCI_FIELDS(SetLoadRequest, m.mass, m.center, m.inertia)
RCI_FIELDS(SetCartImpDesiredTauRequest, m.tau)
RCI_FIELDS(SetFiltersRequest, m.joint_hz, m.cartesian_hz, m.torque_hz)
RCI_FIELDS(SetTorqueFilterCutOffFrequencyRequest, m.hz)
RCI_FIELDS(SetFcCoorRequest, m.frame, m.type)
RCI_FIELDS(EnableVirtualGuideRequest, m.enable, m.stiffness)
RCI_FIELDS(SetDORequest, m.signal, m.state)
RCI_FIELDS(GetDIStateRequest, m.signal)
RCI_FIELDS(StartDragRequest, m.space, m.type)
RCI_FIELDS(ByteResponse, m.value)
RCI_FIELDS(GetDIStateResponse, m.status, m.state)
RCI_FIELDS(LoadRobotModelResponse, m.status, m.dh, m.dims, m.dyn_friction, m.dyn)
#undef RCI_FIELDS
[[maybe_unused]] std::tuple<> fields(const EmptyRequest&) { return {}; }
[[maybe_unused]] std::tuple<> fields(EmptyRequest&) { return {}; }

struct Put {
  ByteWriter& w;
  void operator()(uint8_t v) { w.u8(v); }
  void operator()(uint16_t v) { w.be16(v); }
  void operator()(bool v) { w.boolean(v); }
  void operator()(double v) { w.f64(v); }
  template <size_t N>
  void operator()(const std::array<double, N>& a) { w.f64s(a); }
};

struct Get {
  ByteReader& r;
  void operator()(uint8_t& v) { v = r.u8(); }
  void operator()(uint16_t& v) { v = r.be16(); }
  void operator()(bool& v) { v = r.boolean(); }
  void operator()(double& v) { v = r.f64(); }
  template <size_t N>
  void operator()(std::array<double, N>& a) { r.f64s(a); }
};

template <class M>
Command commandOf(const M& m) {
  if constexpr (requires { M::kCommand; }) return M::kCommand; else return m.command;
}

template <class M>
void writePayload(ByteWriter& w, const M& m) {
  w.be32(static_cast<uint32_t>(commandOf(m)));
  Put put{w};
  std::apply([&](const auto&... f) { (put(f), ...); }, fields(m));
}

template <class M>
size_t payloadSize() {
  std::array<uint8_t, kMaxPayloadSize> scratch{};
  ByteWriter w(scratch.data(), scratch.size());
  M m{};
  writePayload(w, m);
  return w.written();
}

template <class M>
Frame encode(uint32_t sequence, const M& m) {
  std::array<uint8_t, kFrameHeaderSize + kMaxPayloadSize> buf{};
  ByteWriter body(buf.data() + kFrameHeaderSize, kMaxPayloadSize);
  writePayload(body, m);
  ByteWriter head(buf.data(), kFrameHeaderSize);
  head.be16(static_cast<uint16_t>(body.written()));
  head.be32(sequence);
  return Frame(buf.begin(), buf.begin() + kFrameHeaderSize + body.written());
}

template <class M>
DecodeStatus decode(const uint8_t* p, size_t n, M& m, size_t short_form_size = 0) {
  const size_t full = payloadSize<M>();
  if (n != full && (short_form_size == 0 || n != short_form_size)) return DecodeStatus::kWrongLength;
  ByteReader r(p, n);
  const uint32_t code = r.be32();
  if constexpr (requires { M::kCommand; }) {
    if (code != static_cast<uint32_t>(M::kCommand)) return DecodeStatus::kBadValue;
  } else {
    if (!isKnownCommand(code)) return DecodeStatus::kBadValue;
    m.command = static_cast<Command>(code);
  }
  Get get{r};
  if constexpr (std::is_same_v<M, SetJointLimitRequest>) {
    if (n != full) {  // the short form: everything but the trailing auto_limit
      get(m.upper);
      get(m.lower);
      m.auto_limit = false;
      return r.ok() && r.atEnd() ? DecodeStatus::kOk : DecodeStatus::kBadValue;
    }
  }
  std::apply([&](auto&... f) { (get(f), ...); }, fields(m));
  return r.ok() && r.atEnd() ? DecodeStatus::kOk : DecodeStatus::kBadValue;
}

}  // namespace

const char* commandName(Command c) {
  switch (c) {
    case Command::kConnect: return "Connect";
    case Command::kSetMotorPower: return "SetMotorPower";
    case Command::kGetMotorState: return "GetMotorState";
    case Command::kStartMove: return "StartMove";
    case Command::kStopMove: return "StopMove";
    case Command::kSetCartesianLimit: return "SetCartesianLimit";
    case Command::kSetJointLimit: return "SetJointLimit";
    case Command::kSetCollisionBehavior: return "SetCollisionBehavior";
    case Command::kSetJointImpedance: return "SetJointImpedance";
    case Command::kSetCartesianImpedance: return "SetCartesianImpedance";
    case Command::kSetCoor: return "SetCoor";
    case Command::kSetLoad: return "SetLoad";
    case Command::kSetCartImpDesiredTau: return "SetCartImpDesiredTau";
    case Command::kSetFilters: return "SetFilters";
    case Command::kSetTorqueFilterCutOffFrequency: return "SetTorqueFilterCutOffFrequency";
    case Command::kAutomaticErrorRecovery: return "AutomaticErrorRecovery";
    case Command::kLoadRobotModel: return "LoadRobotModel";
    case Command::kSetFcCoor: return "SetFcCoor";
    case Command::kEnableVirtualGuide: return "EnableVirtualGuide";
    case Command::kSetDO: return "SetDO";
    case Command::kGetDIState: return "GetDIState";
    case Command::kStartDrag: return "StartDrag";
    case Command::kStopDrag: return "StopDrag";
    case Command::kGetSafetyStopState: return "GetSafetyStopState";
    case Command::kRebootRobot: return "RebootRobot";
    case Command::kInvalid: return "Invalid";
  }
  return "Unknown";
}

bool isKnownCommand(uint32_t code) { return code <= static_cast<uint32_t>(Command::kRebootRobot); }

const char* toString(SetterStatus s) {
  switch (s) {
    case SetterStatus::kSuccess: return "success";
    case SetterStatus::kNotPossible: return "not possible in the robot's current state";
    case SetterStatus::kInvalidArgument: return "invalid argument";
  }
  return "unknown status";
}

const char* toString(StartMoveStatus s) {
  switch (s) {
    case StartMoveStatus::kSuccess: return "success";
    case StartMoveStatus::kMotionStarted: return "motion started";
    case StartMoveStatus::kPreempted: return "preempted";
    case StartMoveStatus::kNotPossible: return "not possible in the robot's current state";
    case StartMoveStatus::kStartAtSingularPose: return "the robot is at a singular pose";
    case StartMoveStatus::kInvalidArgument: return "invalid argument";
    case StartMoveStatus::kReflexAborted: return "aborted by a reflex (error bits set)";
    case StartMoveStatus::kEmergencyAborted: return "aborted by an emergency stop";
    case StartMoveStatus::kInputErrorAborted: return "aborted by an input error";
    case StartMoveStatus::kAborted: return "aborted";
  }
  return "unknown status";
}

const char* toString(StopMoveStatus s) {
  switch (s) {
    case StopMoveStatus::kSuccess: return "success";
    case StopMoveStatus::kNotPossible: return "not possible in the robot's current state";
    case StopMoveStatus::kEmergencyAborted: return "aborted by an emergency stop";
    case StopMoveStatus::kReflexAborted: return "aborted by a reflex (error bits set)";
    case StopMoveStatus::kAborted: return "aborted";
  }
  return "unknown status";
}

const char* toString(ErrorRecoveryStatus s) {
  switch (s) {
    case ErrorRecoveryStatus::kSuccess: return "success";
    case ErrorRecoveryStatus::kNotPossible: return "not possible in the robot's current state";
    case ErrorRecoveryStatus::kManualRecoveryRequired: return "manual recovery required (release the emergency stop first)";
    case ErrorRecoveryStatus::kReflexAborted: return "aborted by a reflex";
    case ErrorRecoveryStatus::kEmergencyAborted: return "aborted by an emergency stop";
    case ErrorRecoveryStatus::kAborted: return "aborted";
  }
  return "unknown status";
}

FrameHeader decodeFrameHeader(const uint8_t (&bytes)[kFrameHeaderSize]) {
  ByteReader r(bytes, kFrameHeaderSize);
  FrameHeader h;
  h.length = r.be16();
  h.sequence = r.be32();
  return h;
}

Command peekCommand(const uint8_t* payload, size_t size) {
  if (size < 4) return Command::kInvalid;
  ByteReader r(payload, size);
  const uint32_t code = r.be32();
  return isKnownCommand(code) ? static_cast<Command>(code) : Command::kInvalid;
}

#define RCI_CODEC(Type)                                                                          \
  Frame encodeFrame(uint32_t sequence, const Type& m) { return encode(sequence, m); }          \
  DecodeStatus decodePayload(const uint8_t* p, size_t n, Type& m) { return decode(p, n, m); }

RCI_CODEC(EmptyRequest)
RCI_CODEC(ConnectRequest)
RCI_CODEC(SetMotorPowerRequest)
RCI_CODEC(StartMoveRequestMsg)
RCI_CODEC(SetCartesianLimitRequest)
RCI_CODEC(SetCollisionBehaviorRequest)
RCI_CODEC(SetJointImpedanceRequest)
RCI_CODEC(SetCartesianImpedanceRequest)
RCI_CODEC(SetCoorRequest)
RCI_CODEC(SetLoadRequest)
RCI_CODEC(SetCartImpDesiredTauRequest)
RCI_CODEC(SetFiltersRequest)
RCI_CODEC(SetTorqueFilterCutOffFrequencyRequest)
RCI_CODEC(SetFcCoorRequest)
RCI_CODEC(EnableVirtualGuideRequest)
RCI_CODEC(SetDORequest)
RCI_CODEC(GetDIStateRequest)
RCI_CODEC(StartDragRequest)
RCI_CODEC(ByteResponse)
RCI_CODEC(GetDIStateResponse)
RCI_CODEC(LoadRobotModelResponse)
#undef RCI_CODEC

Frame encodeFrame(uint32_t sequence, const ConnectResponse& m) {
  std::array<uint8_t, kFrameHeaderSize + 11> buf{};
  ByteWriter body(buf.data() + kFrameHeaderSize, buf.size() - kFrameHeaderSize);
  body.be32(static_cast<uint32_t>(Command::kConnect));
  body.u8(m.status);
  if (m.has_holder) {
    for (uint8_t b : m.holder_ip) body.u8(b);
    body.be16(m.holder_port);
  }
  ByteWriter head(buf.data(), kFrameHeaderSize);
  head.be16(static_cast<uint16_t>(body.written()));
  head.be32(sequence);
  return Frame(buf.begin(), buf.begin() + kFrameHeaderSize + body.written());
}

DecodeStatus decodePayload(const uint8_t* p, size_t n, ConnectResponse& m) {
  constexpr size_t kBare = 5, kWithHolder = 11;
  if (p == nullptr || n < kBare) return DecodeStatus::kWrongLength;
  ByteReader r(p, n);
  if (r.be32() != static_cast<uint32_t>(Command::kConnect)) return DecodeStatus::kBadValue;
  m = ConnectResponse{};
  m.status = r.u8();
  if (m.status == static_cast<uint8_t>(ConnectStatus::kBusy) && n >= kWithHolder) {
    for (uint8_t& b : m.holder_ip) b = r.u8();
    m.holder_port = r.be16();
    m.has_holder = true;
  }
  return r.ok() ? DecodeStatus::kOk : DecodeStatus::kBadValue;
}

// SetJointLimit: the V2.0 manual appended auto_limit; the 116-byte form without it is accepted.
Frame encodeFrame(uint32_t sequence, const SetJointLimitRequest& m) { return encode(sequence, m); }
DecodeStatus decodePayload(const uint8_t* p, size_t n, SetJointLimitRequest& m) {
  return decode(p, n, m, /*short_form_size=*/116);
}

}  // namespace xmate::protocol
