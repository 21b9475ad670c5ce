// SPDX-License-Identifier: Apache-2.0
// POSIX implementation of TcpConnection/TcpListener: non-blocking descriptors driven by poll().
#include "net/tcp_socket.h"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

#include "net/clock.h"

namespace xmate::net {
namespace {

bool waitFor(int fd, short events, int timeout_ms) {
  pollfd p{fd, events, 0};
  for (;;) {
    const int r = ::poll(&p, 1, timeout_ms);
    if (r > 0) return true;
    if (r == 0) return false;
    if (errno != EINTR) return true;  // let the following call report the error
  }
}

void setNonBlocking(int fd) { ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) | O_NONBLOCK); }

Endpoint endpointOf(int fd, bool peer) {
  Endpoint e;
  socklen_t len = sizeof e.addr;
  if (peer)
    ::getpeername(fd, reinterpret_cast<sockaddr*>(&e.addr), &len);
  else
    ::getsockname(fd, reinterpret_cast<sockaddr*>(&e.addr), &len);
  return e;
}

}  // namespace

const char* toString(IoResult r) {
  switch (r) {
    case IoResult::kOk: return "ok";
    case IoResult::kTimeout: return "timed out";
    case IoResult::kClosed: return "connection closed by the peer";
    case IoResult::kError: return "socket error";
  }
  return "unknown";
}

TcpConnection::~TcpConnection() { close(); }
TcpConnection::TcpConnection(TcpConnection&& o) noexcept : fd_(o.fd_) { o.fd_ = -1; }
TcpConnection& TcpConnection::operator=(TcpConnection&& o) noexcept {
  if (this != &o) {
    close();
    fd_ = o.fd_;
    o.fd_ = -1;
  }
  return *this;
}

TcpConnection TcpConnection::connect(const Endpoint& to, int timeout_ms) {
  const int fd = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
  if (fd < 0) throw std::runtime_error(std::string("cannot open a TCP socket: ") + std::strerror(errno));
  TcpConnection c(fd);
  setNonBlocking(fd);
  const int one = 1;
  ::setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
  if (::connect(fd, reinterpret_cast<const sockaddr*>(&to.addr), sizeof to.addr) != 0) {
    if (errno != EINPROGRESS)
      throw std::runtime_error("cannot connect to " + to.toString() + ": " + std::strerror(errno));
    if (!waitFor(fd, POLLOUT, timeout_ms))
      throw std::runtime_error("no answer from " + to.toString() + " within " + std::to_string(timeout_ms) +
                               " ms (is the controller on and the address right?)");
    int err = 0;
    socklen_t len = sizeof err;
    ::getsockopt(fd, SOL_SOCKET, SO_ERROR, &err, &len);
    if (err != 0) throw std::runtime_error("cannot connect to " + to.toString() + ": " + std::strerror(err));
  }
  return c;
}

IoResult TcpConnection::sendAll(const void* data, size_t size, int timeout_ms) {
  const auto* p = static_cast<const uint8_t*>(data);
  while (size > 0) {
    const long n = ::send(fd_, p, size, MSG_NOSIGNAL);
    if (n > 0) {
      p += n;
      size -= size_t(n);
      continue;
    }
    if (n < 0 && (errno == EAGAIN || errno == EINTR)) {
      if (!waitFor(fd_, POLLOUT, timeout_ms)) return IoResult::kTimeout;
      continue;
    }
    return (n < 0 && errno != EPIPE && errno != ECONNRESET) ? IoResult::kError : IoResult::kClosed;
  }
  return IoResult::kOk;
}

IoResult TcpConnection::readExact(void* data, size_t size, int timeout_ms, size_t* read) {
  auto* const begin = static_cast<uint8_t*>(data);
  auto* p = begin;
  if (read) *read = 0;
  const int64_t deadline = monotonicNs() + int64_t(timeout_ms) * 1'000'000;
  while (size > 0) {
    const long n = ::recv(fd_, p, size, 0);
    if (n > 0) {
      p += n;
      size -= size_t(n);
      if (read) *read = size_t(p - begin);
      continue;
    }
    if (n == 0) return IoResult::kClosed;
    if (errno != EAGAIN && errno != EINTR) return errno == ECONNRESET ? IoResult::kClosed : IoResult::kError;
    int wait_ms = -1;
    if (timeout_ms >= 0) {
      const int64_t left = deadline - monotonicNs();
      if (left <= 0) return IoResult::kTimeout;
      wait_ms = int((left + 999'999) / 1'000'000);
    }
    if (!waitFor(fd_, POLLIN, wait_ms)) return IoResult::kTimeout;
  }
  return IoResult::kOk;
}

void TcpConnection::shutdown() {
  if (fd_ >= 0) ::shutdown(fd_, SHUT_RDWR);
}

void TcpConnection::close() {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
}

Endpoint TcpConnection::peer() const { return endpointOf(fd_, true); }
Endpoint TcpConnection::local() const { return endpointOf(fd_, false); }

TcpListener::~TcpListener() { close(); }

void TcpListener::listen(const std::string& ip, uint16_t port) {
  close();
  const Endpoint local = makeEndpoint(ip, port);
  fd_ = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
  if (fd_ < 0) throw std::runtime_error(std::string("cannot open a TCP socket: ") + std::strerror(errno));
  const int one = 1;
  ::setsockopt(fd_, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
  if (::bind(fd_, reinterpret_cast<const sockaddr*>(&local.addr), sizeof local.addr) != 0 || ::listen(fd_, 4) != 0) {
    const int err = errno;
    close();
    throw std::runtime_error("cannot listen on TCP " + local.toString() + ": " + std::strerror(err) +
                             (err == EADDRINUSE ? " (another controller or simulator already uses this port?)" : ""));
  }
  setNonBlocking(fd_);
}

uint16_t TcpListener::localPort() const { return ntohs(endpointOf(fd_, false).addr.sin_port); }

std::optional<TcpConnection> TcpListener::accept(int timeout_ms) {
  if (fd_ < 0 || !waitFor(fd_, POLLIN, timeout_ms)) return std::nullopt;
  const int fd = ::accept4(fd_, nullptr, nullptr, SOCK_CLOEXEC | SOCK_NONBLOCK);
  if (fd < 0) return std::nullopt;
  const int one = 1;
  ::setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
  return TcpConnection(fd);
}

void TcpListener::shutdown() {
  if (fd_ >= 0) ::shutdown(fd_, SHUT_RDWR);
}

void TcpListener::close() {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
}

}  // namespace xmate::net
