// SPDX-License-Identifier: Apache-2.0
// A non-copyable IPv4 UDP socket for the 1 kHz exchange. send/receive are single system calls and
// allocate nothing; errors other than timeouts are reported as return values, not exceptions,
// so the real-time loop decides what to do.
#pragma once

#include <netinet/in.h>

#include <cstddef>
#include <cstdint>
#include <string>

namespace xmate::net {

struct Endpoint {
  sockaddr_in addr{};
  std::string toString() const;  // "127.0.0.1:1337"
};

// Resolves a dotted IPv4 address (or "localhost") and port; throws std::invalid_argument if bad.
Endpoint makeEndpoint(const std::string& ip, uint16_t port);

class UdpSocket {
 public:
  UdpSocket() = default;
  ~UdpSocket();
  UdpSocket(const UdpSocket&) = delete;
  UdpSocket& operator=(const UdpSocket&) = delete;
  UdpSocket(UdpSocket&& other) noexcept;
  UdpSocket& operator=(UdpSocket&& other) noexcept;

  // Opens and binds; port 0 picks a free port. Throws std::runtime_error with errno text.
  void bind(const std::string& ip, uint16_t port);
  bool isOpen() const { return fd_ >= 0; }
  uint16_t localPort() const;
  void close();

  // Kernel buffer sizes (bytes), best effort; returns the sizes actually granted.
  void setBufferSizes(int receive_bytes, int send_bytes);

  // Returns bytes sent, or -1 (errno kept).
  long sendTo(const Endpoint& to, const void* data, size_t size);
  // Waits up to timeout_us (0 = poll, < 0 = forever). Returns bytes received (the datagram is
  // truncated to capacity, in which case the full length is returned), 0 on timeout, -1 on error.
  long receiveFrom(void* data, size_t capacity, Endpoint* from, int64_t timeout_us);

 private:
  int fd_ = -1;
};

}  // namespace xmate::net
