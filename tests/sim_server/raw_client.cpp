// SPDX-License-Identifier: Apache-2.0
// RawClient: TCP requests with framing, UDP states in and commands out (raw_client.h).
#include "raw_client.h"

#include <stdexcept>
#include <string>

namespace simtest {

using namespace xmate;

protocol::DecodeStatus Datagram::decode(RCI::robot::RobotState& state) const {
  return protocol::decodeRobotState(bytes.data(), size_t(size), state);
}

RawClient::RawClient(uint16_t server_port) {
  udp_.bind("127.0.0.1", 0);
  udp_.setBufferSizes(1 << 21, 1 << 20);
  tcp_ = net::TcpConnection::connect(net::makeEndpoint("127.0.0.1", server_port), 2000);
}

uint8_t RawClient::handshake() { return requestByte(protocol::ConnectRequest{udpPort()}); }

protocol::ConnectResponse RawClient::handshakeResponse() {
  const std::vector<uint8_t> payload = request(protocol::encodeFrame(++sequence_, protocol::ConnectRequest{udpPort()}));
  protocol::ConnectResponse r;
  if (protocol::decodePayload(payload.data(), payload.size(), r) != protocol::DecodeStatus::kOk)
    throw std::runtime_error("response is not a ConnectResponse");
  return r;
}

std::vector<uint8_t> RawClient::request(const protocol::Frame& frame) {
  if (tcp_.sendAll(frame.data(), frame.size(), 2000) != net::IoResult::kOk)
    throw std::runtime_error("cannot send the request");
  uint8_t header[protocol::kFrameHeaderSize];
  // Generous: in lock-step the simulator may be waiting out a lost answer first.
  net::IoResult r = tcp_.readExact(header, sizeof header, 10000);
  if (r != net::IoResult::kOk) throw std::runtime_error(std::string("no response header: ") + net::toString(r));
  const protocol::FrameHeader h = protocol::decodeFrameHeader(header);
  std::vector<uint8_t> payload(h.length);
  r = tcp_.readExact(payload.data(), payload.size(), 10000);
  if (r != net::IoResult::kOk) throw std::runtime_error(std::string("no response payload: ") + net::toString(r));
  const uint32_t sent = uint32_t(frame[2]) << 24 | uint32_t(frame[3]) << 16 | uint32_t(frame[4]) << 8 | frame[5];
  if (h.sequence != sent) throw std::runtime_error("response carries another sequence number");
  return payload;
}

bool RawClient::digitalInput(uint8_t signal) {
  const std::vector<uint8_t> payload = request(protocol::encodeFrame(++sequence_, protocol::GetDIStateRequest{signal}));
  protocol::GetDIStateResponse r;
  if (protocol::decodePayload(payload.data(), payload.size(), r) != protocol::DecodeStatus::kOk || r.status != 0)
    throw std::runtime_error("GetDIState failed");
  return r.state;
}

std::optional<Datagram> RawClient::receive(int timeout_ms) {
  Datagram d;
  net::Endpoint from;
  const long n = udp_.receiveFrom(d.bytes.data(), d.bytes.size(), &from, int64_t(timeout_ms) * 1000);
  if (n <= 0) return std::nullopt;
  d.size = n;
  server_udp_ = from;
  return d;
}

std::optional<RCI::robot::RobotState> RawClient::receiveState(int timeout_ms) {
  const std::optional<Datagram> d = receive(timeout_ms);
  if (!d) return std::nullopt;
  RCI::robot::RobotState state;
  const protocol::DecodeStatus status = d->decode(state);
  if (status != protocol::DecodeStatus::kOk)
    throw std::runtime_error(std::string("a state did not decode: ") + protocol::toString(status));
  return state;
}

int RawClient::drain() {
  int n = 0;
  while (receive(0)) ++n;
  return n;
}

void RawClient::answer(const RCI::robot::RobotState& state, bool finished) {
  RCI::robot::RobotCommand command;
  command.message_id = state.message_id;
  command.motion.q_c = state.q;
  command.motion.toolTobase_pos_c = state.toolTobase_pos_m;
  command.motion.motion_generation_finished = finished;
  protocol::RobotCommandBuffer bytes{};
  protocol::encodeRobotCommand(command, bytes);
  sendRaw(bytes.data(), bytes.size());
}

void RawClient::sendRaw(const void* data, size_t size) {
  if (!server_udp_) throw std::runtime_error("no state received yet: the simulator's UDP endpoint is unknown");
  if (udp_.sendTo(*server_udp_, data, size) != long(size)) throw std::runtime_error("cannot send a datagram");
}

}  // namespace simtest
