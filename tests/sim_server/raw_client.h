// SPDX-License-Identifier: Apache-2.0
// A minimal RCI client for the simulator tests, built directly on the protocol codecs and the
// sockets (not on xmate::Robot): it shows exactly what goes over the wire.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <vector>

#include <xmate/rci_types.h>

#include "net/tcp_socket.h"
#include "net/udp_socket.h"
#include "protocol/realtime_codec.h"
#include "protocol/tcp_codec.h"

namespace simtest {

// One received datagram, as it came (size is the real length, even if longer than the buffer).
struct Datagram {
  std::array<uint8_t, 2048> bytes{};
  long size = 0;
  xmate::protocol::DecodeStatus decode(RCI::robot::RobotState& state) const;
};

class RawClient {
 public:
  // Opens a UDP socket on a free loopback port and connects TCP to the simulator.
  explicit RawClient(uint16_t server_port);

  // Sends ConnectRequest{our UDP port}; returns the status byte of ConnectResponse.
  uint8_t handshake();
  // The same, returning the whole ConnectResponse (a busy simulator names the session's holder).
  xmate::protocol::ConnectResponse handshakeResponse();
  // Sends a request and returns the response payload (without the frame header). Throws
  // std::runtime_error if the response does not come, or has another sequence number.
  std::vector<uint8_t> request(const xmate::protocol::Frame& frame);
  // Convenience: the request's single status/state byte (ByteResponse).
  template <class Request>
  uint8_t requestByte(const Request& request_message) {
    const std::vector<uint8_t> payload = request(xmate::protocol::encodeFrame(++sequence_, request_message));
    xmate::protocol::ByteResponse r;
    if (xmate::protocol::decodePayload(payload.data(), payload.size(), r) != xmate::protocol::DecodeStatus::kOk)
      throw std::runtime_error("response is not a one-byte status");
    return r.value;
  }
  uint8_t requestByte(xmate::protocol::Command command) {
    return requestByte(xmate::protocol::EmptyRequest{command});
  }
  // GetDIState: the level of input signal (0..5); throws if the status is not success.
  bool digitalInput(uint8_t signal);

  // Waits up to timeout_ms for one datagram; remembers where it came from (the simulator's UDP).
  std::optional<Datagram> receive(int timeout_ms);
  // Waits for the next datagram that decodes as a RobotState; throws if it does not decode.
  std::optional<RCI::robot::RobotState> receiveState(int timeout_ms);
  // Drops every datagram already queued; returns how many.
  int drain();
  // Answers state with a command holding the measured position (q_c = q, the same message_id).
  void answer(const RCI::robot::RobotState& state, bool finished = false);
  void sendRaw(const void* data, size_t size);

  xmate::net::TcpConnection& tcp() { return tcp_; }
  uint16_t udpPort() const { return udp_.localPort(); }

 private:
  xmate::net::UdpSocket udp_;
  xmate::net::TcpConnection tcp_;
  std::optional<xmate::net::Endpoint> server_udp_;
  uint32_t sequence_ = 0;
};

}  // namespace simtest
