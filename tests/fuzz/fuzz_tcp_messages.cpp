// SPDX-License-Identifier: Apache-2.0
// libFuzzer target for the TCP channel. The input is one payload (starting with the Command code);
// it goes to the request decoder its first four bytes name, to every response decoder, and to
// sim::Controller::handleRequest. Nothing may crash, and the controller must answer every request
// with a well-formed frame: the length field right, the sequence echoed, and -- for a known
// command -- a response that decodes as that command's response type (or the five-byte
// {kInvalid, status} the controller sends for a request it could not parse).
#include <memory>

#include "protocol/tcp_codec.h"
#include "sim/controller.h"

namespace {

using namespace xmate::protocol;

template <class Message>
void decodeAs(const uint8_t* data, size_t size) {
  Message m{};
  (void)decodePayload(data, size, m);
}

void decodeRequest(Command command, const uint8_t* data, size_t size) {
  switch (command) {
    case Command::kConnect: return decodeAs<ConnectRequest>(data, size);
    case Command::kSetMotorPower: return decodeAs<SetMotorPowerRequest>(data, size);
    case Command::kStartMove: return decodeAs<StartMoveRequestMsg>(data, size);
    case Command::kSetCartesianLimit: return decodeAs<SetCartesianLimitRequest>(data, size);
    case Command::kSetJointLimit: return decodeAs<SetJointLimitRequest>(data, size);
    case Command::kSetCollisionBehavior: return decodeAs<SetCollisionBehaviorRequest>(data, size);
    case Command::kSetJointImpedance: return decodeAs<SetJointImpedanceRequest>(data, size);
    case Command::kSetCartesianImpedance: return decodeAs<SetCartesianImpedanceRequest>(data, size);
    case Command::kSetCoor: return decodeAs<SetCoorRequest>(data, size);
    case Command::kSetLoad: return decodeAs<SetLoadRequest>(data, size);
    case Command::kSetCartImpDesiredTau: return decodeAs<SetCartImpDesiredTauRequest>(data, size);
    case Command::kSetFilters: return decodeAs<SetFiltersRequest>(data, size);
    case Command::kSetTorqueFilterCutOffFrequency: return decodeAs<SetTorqueFilterCutOffFrequencyRequest>(data, size);
    case Command::kSetFcCoor: return decodeAs<SetFcCoorRequest>(data, size);
    case Command::kEnableVirtualGuide: return decodeAs<EnableVirtualGuideRequest>(data, size);
    case Command::kSetDO: return decodeAs<SetDORequest>(data, size);
    case Command::kGetDIState: return decodeAs<GetDIStateRequest>(data, size);
    case Command::kStartDrag: return decodeAs<StartDragRequest>(data, size);
    default: return decodeAs<EmptyRequest>(data, size);
  }
}

void decodeResponses(const uint8_t* data, size_t size) {
  decodeAs<ByteResponse>(data, size);
  decodeAs<ConnectResponse>(data, size);
  decodeAs<GetDIStateResponse>(data, size);
  decodeAs<LoadRobotModelResponse>(data, size);
}

// The response frame must be consistent with the request it answers.
void checkResponse(const Frame& frame, uint32_t sequence, Command command) {
  if (frame.size() < kFrameHeaderSize + 4 || frame.size() > kFrameHeaderSize + kMaxPayloadSize) __builtin_trap();
  uint8_t header[kFrameHeaderSize];
  for (size_t i = 0; i < kFrameHeaderSize; ++i) header[i] = frame[i];
  const FrameHeader h = decodeFrameHeader(header);
  if (h.length != frame.size() - kFrameHeaderSize || h.sequence != sequence) __builtin_trap();
  if (command == Command::kInvalid) return;
  const uint8_t* payload = frame.data() + kFrameHeaderSize;
  // A request the controller could not parse may be answered {kInvalid, status}: 0xFF + one byte.
  if (peekCommand(payload, h.length) == Command::kInvalid) {
    if (h.length != 5 || payload[0] != 0 || payload[1] != 0 || payload[2] != 0 || payload[3] != 0xFF) __builtin_trap();
    return;
  }
  DecodeStatus status;
  if (command == Command::kGetDIState) {
    GetDIStateResponse r;
    status = decodePayload(payload, h.length, r);
  } else if (command == Command::kLoadRobotModel) {
    // Answered with the model on success, or with a bare status when refused.
    LoadRobotModelResponse full;
    ByteResponse bare;
    status = decodePayload(payload, h.length, full);
    if (status != DecodeStatus::kOk) status = decodePayload(payload, h.length, bare);
  } else {
    ByteResponse r;
    status = decodePayload(payload, h.length, r);
    if (status == DecodeStatus::kOk && r.command != command) __builtin_trap();
  }
  if (status != DecodeStatus::kOk) __builtin_trap();
}

xmate::sim::Controller& controller() {
  static std::unique_ptr<xmate::sim::Controller> c;
  if (!c || c->rebootRequested()) c = std::make_unique<xmate::sim::Controller>();
  return *c;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const Command command = peekCommand(data, size);
  decodeRequest(command, data, size);
  decodeResponses(data, size);
  if (size >= kFrameHeaderSize) {
    uint8_t header[kFrameHeaderSize];
    for (size_t i = 0; i < kFrameHeaderSize; ++i) header[i] = data[i];
    (void)decodeFrameHeader(header);
  }
  if (size > kMaxPayloadSize) return 0;  // the server never reads a longer payload
  const uint32_t sequence = uint32_t(size * 2654435761u);
  checkResponse(controller().handleRequest(sequence, data, size), sequence, command);
  return 0;
}
