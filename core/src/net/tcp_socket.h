// SPDX-License-Identifier: Apache-2.0
// IPv4 TCP connections and a listener with explicit timeouts, for the RCI command channel
// (client side: one session per robot; simulator side: the controller's port).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

#include "net/udp_socket.h"  // Endpoint

namespace xmate::net {

enum class IoResult { kOk, kTimeout, kClosed, kError };
const char* toString(IoResult r);

class TcpConnection {
 public:
  TcpConnection() = default;
  explicit TcpConnection(int fd) : fd_(fd) {}
  ~TcpConnection();
  TcpConnection(const TcpConnection&) = delete;
  TcpConnection& operator=(const TcpConnection&) = delete;
  TcpConnection(TcpConnection&& other) noexcept;
  TcpConnection& operator=(TcpConnection&& other) noexcept;

  // Connects within timeout_ms. Throws std::runtime_error saying why (refused, timed out, ...).
  static TcpConnection connect(const Endpoint& to, int timeout_ms);

  bool isOpen() const { return fd_ >= 0; }
  // Writes all bytes or fails; each wait for the socket is bounded by timeout_ms.
  IoResult sendAll(const void* data, size_t size, int timeout_ms);
  // Reads exactly size bytes; waits at most timeout_ms in total (< 0: forever). *read (optional)
  // gets how many bytes arrived, also when it fails (a timeout after part of a frame).
  IoResult readExact(void* data, size_t size, int timeout_ms, size_t* read = nullptr);
  // Wakes any thread blocked on this connection (it sees kClosed) without closing the descriptor.
  void shutdown();
  void close();
  Endpoint peer() const;
  Endpoint local() const;

 private:
  int fd_ = -1;
};

class TcpListener {
 public:
  TcpListener() = default;
  ~TcpListener();
  TcpListener(const TcpListener&) = delete;
  TcpListener& operator=(const TcpListener&) = delete;

  // Binds and listens (SO_REUSEADDR). Port 0 picks a free port. Throws std::runtime_error.
  void listen(const std::string& ip, uint16_t port);
  uint16_t localPort() const;
  // Waits up to timeout_ms for a connection; nullopt on timeout or after shutdown().
  std::optional<TcpConnection> accept(int timeout_ms);
  void shutdown();
  void close();
  bool isOpen() const { return fd_ >= 0; }

 private:
  int fd_ = -1;
};

}  // namespace xmate::net
