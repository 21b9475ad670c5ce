// SPDX-License-Identifier: Apache-2.0
// Request/response over the TCP command channel: framing, sequence matching, timeouts, errors.
#include "client/tcp_session.h"

#include <xmate/exception.h>

#include "net/clock.h"

namespace xmate::client {

void TcpSession::open(const net::Endpoint& controller, int timeout_ms) {
  std::lock_guard lock(mutex_);
  controller_ = controller;
  try {
    net::TcpConnection connected = net::TcpConnection::connect(controller, timeout_ms);
    std::lock_guard fd_lock(fd_mutex_);
    connection_ = std::move(connected);
  } catch (const std::exception& e) {
    throw TcpException(std::string("connect: ") + e.what() +
                       "; check the controller's IP address and port and that it is in RCI mode");
  }
  open_.store(true, std::memory_order_release);
}

void TcpSession::close() {
  {
    std::lock_guard fd_lock(fd_mutex_);
    connection_.shutdown();  // wakes a reader blocked in exchange() on another thread
  }
  std::lock_guard lock(mutex_);
  closeConnection();
  open_.store(false, std::memory_order_release);
}

void TcpSession::closeConnection() {
  std::lock_guard fd_lock(fd_mutex_);
  connection_.close();
}

net::Endpoint TcpSession::local() const {
  std::lock_guard fd_lock(fd_mutex_);
  return connection_.local();
}

void TcpSession::fail(const char* call, const char* what, net::IoResult result, int timeout_ms, bool mid_frame) {
  std::string message = std::string(call) + ": " + what + " " + controller_.toString() + ": ";
  if (result == net::IoResult::kTimeout && mid_frame) {
    // Part of a frame was read: every later answer would be read from the middle of this one.
    closeConnection();
    open_.store(false, std::memory_order_release);
    throw TcpException(message + "the response stopped in the middle of a frame for " + std::to_string(timeout_ms) +
                       " ms; the session is closed because the rest of the stream cannot be trusted: "
                       "call reconnect()");
  }
  if (result == net::IoResult::kTimeout) {
    // The session stays usable: a late response is recognised by its sequence number and skipped.
    throw TcpException(message + "no response within " + std::to_string(timeout_ms) +
                       " ms; check the IP and port and that the controller is in RCI mode");
  }
  closeConnection();
  open_.store(false, std::memory_order_release);
  if (result == net::IoResult::kClosed)  // someone answered at this address: the IP and port are right
    throw TcpException(message +
                       "the controller closed the connection without answering (it may be busy with another "
                       "program's session, rebooting or shutting down); the session is closed: call reconnect() "
                       "when the controller is free");
  throw TcpException(message + net::toString(result) +
                     "; the session is closed: check the IP and port, then call reconnect()");
}

std::vector<uint8_t> TcpSession::exchange(const char* call, const std::function<protocol::Frame(uint32_t)>& encode,
                                          protocol::Command expected, int timeout_ms) {
  std::lock_guard lock(mutex_);
  if (!connection_.isOpen())
    throw TcpException(std::string(call) + ": no session with the controller; call connect() or reconnect()");
  const uint32_t sequence = ++sequence_;
  const protocol::Frame frame = encode(sequence);
  if (const auto r = connection_.sendAll(frame.data(), frame.size(), timeout_ms); r != net::IoResult::kOk)
    fail(call, "cannot send to", r, timeout_ms);

  const int64_t deadline = net::monotonicNs() + int64_t(timeout_ms) * 1'000'000;
  for (;;) {
    const int remaining_ms = int(std::max<int64_t>(0, (deadline - net::monotonicNs()) / 1'000'000));
    uint8_t header_bytes[protocol::kFrameHeaderSize];
    size_t header_read = 0;
    if (const auto r = connection_.readExact(header_bytes, sizeof header_bytes, remaining_ms, &header_read);
        r != net::IoResult::kOk)
      fail(call, "no response from", r, timeout_ms, header_read > 0);
    const protocol::FrameHeader header = protocol::decodeFrameHeader(header_bytes);
    if (header.length > protocol::kMaxPayloadSize)
      throw ProtocolException(std::string(call) + ": the controller sent a frame of " + std::to_string(header.length) +
                              " bytes (at most " + std::to_string(protocol::kMaxPayloadSize) +
                              " expected); it speaks another protocol version");
    std::vector<uint8_t> payload(header.length);
    if (const auto r = connection_.readExact(payload.data(), payload.size(), std::max(remaining_ms, 100));
        r != net::IoResult::kOk)
      fail(call, "incomplete response from", r, timeout_ms, true);
    if (header.sequence != sequence) continue;  // the late answer to an earlier, timed-out request
    const protocol::Command got = protocol::peekCommand(payload.data(), payload.size());
    if (got != expected)
      throw ProtocolException(std::string(call) + ": the controller answered with command " +
                              protocol::commandName(got) + " instead of " + protocol::commandName(expected) +
                              "; it speaks another protocol version");
    return payload;
  }
}

}  // namespace xmate::client
