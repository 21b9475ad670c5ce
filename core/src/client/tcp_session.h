// SPDX-License-Identifier: Apache-2.0
// The TCP command channel of one session: frames with increasing sequence numbers, one request at a
// time, each answered within a timeout (docs/protocol.md, "TCP framing", "Timeouts").
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <mutex>
#include <vector>

#include "net/tcp_socket.h"
#include "protocol/tcp_codec.h"

namespace xmate::client {

class TcpSession {
 public:
  // Connects within timeout_ms. Throws TcpException naming the address and the reason.
  void open(const net::Endpoint& controller, int timeout_ms);
  // Closes the connection; wakes a request in progress on another thread. Safe to call twice.
  void close();
  bool isOpen() const { return open_.load(std::memory_order_acquire); }
  // Our end of the connection (its IP is the interface that reaches the controller).
  net::Endpoint local() const;

  // Sends the frame encode(sequence) and returns the payload of the response carrying the same
  // sequence (older responses, left over from a request that timed out, are skipped).
  // Throws TcpException on timeout or a broken connection (the session is then closed) and
  // ProtocolException when the response is malformed or answers another command. call names the
  // API call in the messages.
  std::vector<uint8_t> exchange(const char* call, const std::function<protocol::Frame(uint32_t)>& encode,
                                protocol::Command expected, int timeout_ms);

 private:
  // Throws TcpException for a failed exchange; closes the session unless it was a timeout with no
  // byte of the frame read (mid_frame false), after which the stream is still aligned.
  [[noreturn]] void fail(const char* call, const char* what, net::IoResult result, int timeout_ms,
                         bool mid_frame = false);
  // Closes the descriptor; with mutex_ held.
  void closeConnection();

  std::mutex mutex_;  // one request/response at a time (callers may be on several threads)
  // The descriptor changes (connect, close) with both mutexes held, in this order; close()'s
  // shutdown and local() need only fd_mutex_, so they never wait for a request in progress and
  // never see a descriptor that is being closed (or already reused by another socket).
  mutable std::mutex fd_mutex_;
  net::TcpConnection connection_;
  net::Endpoint controller_;
  uint32_t sequence_ = 0;
  std::atomic<bool> open_{false};
};

}  // namespace xmate::client
